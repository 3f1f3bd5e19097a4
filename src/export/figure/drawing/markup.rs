//! The figures' text markup: `f_s` and `N^-1` as sub- and superscripts, everything else literal.

/// Size of sub- and superscripts relative to the text.
pub(crate) const SCRIPT_SIZE: f32 = 0.7;

/// Where a run of text sits: on the baseline, or as a sub- or superscript.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Script {
    Normal,
    Sub,
    Super,
}

/// Splits `text` into runs of normal text, subscripts and superscripts. The figures write
/// subscripts as `f_s`, `F_r`, `Φ_p1` and superscripts as `N^s`, `N^-1`: a `_` or `^` right
/// after a one-letter symbol (a letter not preceded by a letter or digit; for `^` also a
/// number: `10^-3`), followed by one or
/// two letters or digits (a superscript may start with a minus) and then nothing that
/// continues a word or another marker, marks a script; the marker is not drawn. Anything
/// else is literal (`per_pixel`, `my_scene_v2`, `a_b_c`, a lone `^`), so that the labels users
/// write stay as they are.
pub(super) fn scripts(text: &str) -> Vec<(Script, String)> {
    let chars: Vec<char> = text.chars().collect();
    let mut out: Vec<(Script, String)> = Vec::new();
    let mut push = |kind: Script, c: char| match out.last_mut() {
        Some((k, s)) if *k == kind => s.push(c),
        _ => out.push((kind, c.to_string())),
    };
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        // The symbol: one letter, not the end of a word.
        let after_symbol = i > 0
            && chars[i - 1].is_alphabetic()
            && !(i > 1 && (chars[i - 2].is_alphanumeric() || matches!(chars[i - 2], '_' | '^')));
        // A power of a number: digits not ending a word (10^-3).
        let after_number = c == '^' && i > 0 && chars[i - 1].is_ascii_digit() && {
            let mut k = i - 1;
            while k > 0 && chars[k - 1].is_ascii_digit() {
                k -= 1;
            }
            k == 0 || !(chars[k - 1].is_alphanumeric() || matches!(chars[k - 1], '_' | '^' | '.'))
        };
        if (c == '_' || c == '^') && (after_symbol || after_number) {
            let mut j = i + 1;
            if c == '^' && matches!(chars.get(j), Some('-' | '−')) {
                j += 1;
            }
            let start = j;
            while j < chars.len() && chars[j].is_alphanumeric() && j - start < 3 {
                j += 1;
            }
            let len = j - start;
            let ends = !chars
                .get(j)
                .is_some_and(|c| c.is_alphanumeric() || *c == '_' || *c == '^');
            if (1..=2).contains(&len) && ends {
                let kind = if c == '_' { Script::Sub } else { Script::Super };
                for &d in &chars[i + 1..j] {
                    push(kind, if d == '-' { '−' } else { d });
                }
                i = j;
                continue;
            }
        }
        push(Script::Normal, c);
        i += 1;
    }
    out
}
