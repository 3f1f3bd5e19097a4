//! Finds where a field path (`columns[1].pattern.cols`, `recon.mode.spp`) is written in a
//! scene's RON text, so that a value refused by [`super::Scene::validate`] is reported with its
//! line and column like a parse error.
//!
//! The scanner knows only what it needs of RON: structs `(a: …)` and maps `{…}` with an optional
//! name before them (`Scene(…)`, `Some(…)`, `Supersample(spp: 4)`), lists `[…]`, strings (with
//! escapes and raw strings), characters and comments. A path that is not written out (a field
//! left at its default) resolves to the innermost part that is: its enclosing struct.

/// One step of a field path.
#[derive(Debug, Clone, PartialEq)]
enum Seg<'a> {
    Field(&'a str),
    Index(usize),
}

fn parse_path(path: &str) -> Vec<Seg<'_>> {
    let mut out = Vec::new();
    for part in path.split('.') {
        let (name, rest) = match part.find('[') {
            Some(i) => (&part[..i], &part[i..]),
            None => (part, ""),
        };
        if !name.is_empty() {
            out.push(Seg::Field(name));
        }
        for idx in rest.split('[').skip(1) {
            if let Ok(i) = idx.trim_end_matches(']').parse() {
                out.push(Seg::Index(i));
            }
        }
    }
    out
}

/// 1-based (line, column) of byte offset `pos` (the column counts characters).
fn line_col(text: &str, pos: usize) -> (usize, usize) {
    let before = &text[..pos.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[start..].chars().count() + 1)
}

fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// Skips whitespace and comments from `pos`.
fn skip_ws(b: &[u8], mut pos: usize) -> usize {
    loop {
        while pos < b.len() && b[pos].is_ascii_whitespace() {
            pos += 1;
        }
        if b[pos..].starts_with(b"//") {
            while pos < b.len() && b[pos] != b'\n' {
                pos += 1;
            }
        } else if b[pos..].starts_with(b"/*") {
            let mut depth = 0usize;
            while pos < b.len() {
                if b[pos..].starts_with(b"/*") {
                    depth += 1;
                    pos += 2;
                } else if b[pos..].starts_with(b"*/") {
                    depth -= 1;
                    pos += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    pos += 1;
                }
            }
        } else {
            return pos;
        }
    }
}

/// The end of the string, raw string or character literal starting at `pos`.
fn skip_literal(b: &[u8], pos: usize) -> usize {
    if b[pos] == b'r' {
        let mut hashes = 0;
        let mut p = pos + 1;
        while p < b.len() && b[p] == b'#' {
            hashes += 1;
            p += 1;
        }
        p += 1; // the opening quote
        while p < b.len() {
            if b[p] == b'"'
                && b[p + 1..]
                    .iter()
                    .take(hashes)
                    .filter(|&&c| c == b'#')
                    .count()
                    == hashes
            {
                return p + 1 + hashes;
            }
            p += 1;
        }
        return b.len();
    }
    let quote = b[pos];
    let mut p = pos + 1;
    while p < b.len() && b[p] != quote {
        if b[p] == b'\\' {
            p += 1;
        }
        p += 1;
    }
    (p + 1).min(b.len())
}

fn starts_raw_string(b: &[u8], pos: usize) -> bool {
    b[pos] == b'r' && matches!(b.get(pos + 1), Some(b'"') | Some(b'#'))
}

/// Tokens at depth 0 of the container whose contents start at `pos`: calls `visit(start,
/// token)` for every identifier and every comma at that depth (token b","), until the
/// container closes. `visit` returns `Some` to stop.
fn scan<T>(
    b: &[u8],
    mut pos: usize,
    mut visit: impl FnMut(usize, &[u8]) -> Option<T>,
) -> Option<T> {
    let mut depth = 0usize;
    while pos < b.len() {
        pos = skip_ws(b, pos);
        if pos >= b.len() {
            break;
        }
        let c = b[pos];
        if c == b'"' || c == b'\'' || starts_raw_string(b, pos) {
            pos = skip_literal(b, pos);
        } else if matches!(c, b'(' | b'[' | b'{') {
            depth += 1;
            pos += 1;
        } else if matches!(c, b')' | b']' | b'}') {
            if depth == 0 {
                return None;
            }
            depth -= 1;
            pos += 1;
        } else if is_ident(c) {
            let start = pos;
            while pos < b.len() && (is_ident(b[pos]) || b[pos] == b'#') {
                pos += 1;
            }
            if depth == 0 {
                if let Some(t) = visit(start, &b[start..pos]) {
                    return Some(t);
                }
            }
        } else {
            if depth == 0 && c == b',' {
                if let Some(t) = visit(pos, b",") {
                    return Some(t);
                }
            }
            pos += 1;
        }
    }
    None
}

/// Inside the compound value starting at `pos` (after an optional name): the offset just
/// after its opening bracket.
fn enter(b: &[u8], pos: usize) -> Option<usize> {
    let mut p = skip_ws(b, pos);
    while p < b.len() && is_ident(b[p]) {
        p += 1;
    }
    p = skip_ws(b, p);
    matches!(b.get(p), Some(b'(') | Some(b'[') | Some(b'{')).then_some(p + 1)
}

/// (offset of the field name, offset of its value) of field `name` in the struct at `pos`.
fn field(b: &[u8], pos: usize, name: &str) -> Option<(usize, usize)> {
    scan(b, pos, |start, tok| {
        if tok == name.as_bytes() {
            let after = skip_ws(b, start + tok.len());
            if b.get(after) == Some(&b':') {
                return Some((start, after + 1));
            }
        }
        None
    })
}

/// Offset of element `index` of the list whose contents start at `pos`.
fn element(b: &[u8], pos: usize, index: usize) -> Option<usize> {
    if index == 0 {
        let p = skip_ws(b, pos);
        return (!matches!(b.get(p), Some(b']') | None)).then_some(p);
    }
    let mut commas = 0;
    let comma = scan(b, pos, |start, tok| {
        if tok == b"," {
            commas += 1;
            if commas == index {
                return Some(start);
            }
        }
        None
    })?;
    let p = skip_ws(b, comma + 1);
    (!matches!(b.get(p), Some(b']') | None)).then_some(p)
}

/// The 1-based (line, column) where `path` is written in `text` (or the innermost enclosing
/// part that is written); `None` when not even the top-level struct is found.
pub fn locate(text: &str, path: &str) -> Option<(usize, usize)> {
    let b = text.as_bytes();
    let mut inside = enter(b, 0)?;
    let mut best = skip_ws(b, 0);
    let segs = parse_path(path);
    for (k, seg) in segs.iter().enumerate() {
        let (at, value) = match seg {
            Seg::Field(name) => match field(b, inside, name) {
                Some(found) => found,
                None => break,
            },
            Seg::Index(i) => match element(b, inside, *i) {
                Some(p) => (p, p),
                None => break,
            },
        };
        best = at;
        if k + 1 == segs.len() {
            break;
        }
        match enter(b, value) {
            Some(p) => inside = p,
            None => break,
        }
    }
    Some(line_col(text, best))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = r##"// a comment (with a bracket
Scene(
    title: "a (tricky) title, with: colons",
    n: 256,
    columns: [
        (pattern: (kind: "jitter", cols: 4), seed: 1),
        /* second */ (pattern: (kind: "grid", cols: 7), label: r#"x "y" ]"#),
    ],
    recon: (size: 64, mode: Supersample(spp: 2000)),
    spectrum: (size: 32),
)
"##;

    #[test]
    fn finds_fields_list_elements_and_enum_payloads() {
        assert_eq!(locate(SCENE, "n"), Some((4, 5)));
        assert_eq!(locate(SCENE, "columns[1].pattern.cols"), Some((7, 47)));
        assert_eq!(locate(SCENE, "columns[0].pattern.cols"), Some((6, 36)));
        assert_eq!(locate(SCENE, "recon.mode.spp"), Some((9, 41)));
        assert_eq!(locate(SCENE, "spectrum.size"), Some((10, 16)));
    }

    #[test]
    fn a_field_not_written_resolves_to_its_enclosing_struct() {
        // columns[0] has no `label`: the column itself.
        assert_eq!(locate(SCENE, "columns[0].label"), Some((6, 9)));
        // No element 5: the `columns` field.
        assert_eq!(locate(SCENE, "columns[5].seed"), Some((5, 5)));
        assert_eq!(locate(SCENE, "signal.k"), Some((2, 1)));
        assert_eq!(locate("", "n"), None);
    }

    #[test]
    fn unclosed_input_does_not_loop_or_panic() {
        for text in [
            "Scene(",
            "Scene(n: [",
            "(\"",
            "(r#\"",
            "(/*",
            "((((",
            "(a: 'x",
        ] {
            let _ = locate(text, "n.x[3].y");
        }
    }
}
