//! How the process's allocator treats large buffers: two settings of glibc's `mallopt` for
//! two kinds of process (elsewhere both are no-ops that report success), and the global
//! allocator [`Allocator`], which in one-shot commands puts buffers of 2 MiB or more on huge
//! pages.
//!
//! - A one-shot command (`points`, `analyze`, `render`, …) wants its peak memory to be its
//!   working set, which the budget's estimates count ([`release_large_buffers`]).
//! - The interactive app wants a slider change to reuse the pages the last change freed
//!   ([`keep_freed_buffers`]): with every large buffer mapped and unmapped on its own, each
//!   change faulted in and zeroed its 512² images afresh and unmapping the old ones cost TLB
//!   shootdowns on every core; the default scene's picture p50 was 17.6–17.7 ms that way
//!   against 10.5–11.9 ms with the buffers kept (BENCHMARKS.md, "Interactive update").

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, Ordering};

/// Buffers of at least this many bytes are mapped and unmapped on their own in one-shot
/// commands (glibc's initial value, fixed).
pub const RELEASE_MMAP_THRESHOLD: usize = 128 << 10;

/// The interactive app's mmap threshold: every buffer of one change (a 512² image of f64 is
/// 2 MiB, the splat's sums 4 MiB) comes from the heap.
pub const KEEP_MMAP_THRESHOLD: usize = 64 << 20;
/// The free memory at the top of the heap the interactive app keeps instead of returning it.
pub const KEEP_TRIM_THRESHOLD: usize = 256 << 20;
/// What the interactive app's heap grows by at a time, so that a change's buffers do not
/// each move the heap's end.
pub const KEEP_TOP_PAD: usize = 64 << 20;

/// Makes glibc return freed large buffers to the system: a fixed mmap threshold of 128 KiB
/// (glibc's initial value; fixing it turns off the dynamic threshold). With the dynamic one,
/// a buffer freed after the first iteration raises the threshold, later buffers of that size
/// come from the heap, and the heap fragments: 40 Lloyd iterations on 10⁵ points peaked at
/// 151 MiB for a 25 MiB working set (and the peak grew with the iterations), a convergence
/// study of Lloyd sets at N = 16384 52 MiB for 10. The budget's memory estimates count working
/// sets (`core::budget`), which this keeps the measured peak close to. Call it before other
/// threads start. Whether every setting was taken.
pub fn release_large_buffers() -> bool {
    HUGE_PAGES.store(true, Ordering::Relaxed);
    set(&[(M_MMAP_THRESHOLD, RELEASE_MMAP_THRESHOLD)])
}

/// The size of a transparent huge page on x86-64 and aarch64 (4 KiB base pages).
pub const HUGE_PAGE: usize = 2 << 20;

/// Whether buffers of [`HUGE_PAGE`] bytes or more are placed on huge-page boundaries and
/// advised as huge pages ([`Allocator`]); set by [`release_large_buffers`].
static HUGE_PAGES: AtomicBool = AtomicBool::new(false);

/// The process's allocator: the system's (glibc's malloc, set by the functions above), except
/// that in one-shot commands a buffer of [`HUGE_PAGE`] bytes or more starts on a huge-page
/// boundary and is advised as huge pages (`madvise(MADV_HUGEPAGE)`), so that the kernel maps
/// it 2 MiB at a time where transparent huge pages are offered (`enabled` = `madvise` or
/// `always`) instead of taking one page fault per 4 KiB. A one-shot command's large buffers
/// are each mapped afresh (the 128 KiB threshold), and their page faults were a fifth of
/// `analyze`'s time (BENCHMARKS.md). Elsewhere, or where the kernel has no huge pages, it is
/// glibc's malloc unchanged. Memory is freed by `free` either way.
pub struct Allocator;

impl Allocator {
    fn huge(size: usize) -> bool {
        size >= HUGE_PAGE && HUGE_PAGES.load(Ordering::Relaxed)
    }
}

// SAFETY: every block comes from `System` with at least the requested alignment and size;
// `System::dealloc` frees any of them whatever its alignment (`free`), so a block allocated
// huge and freed (or grown) with the caller's layout is freed correctly.
unsafe impl GlobalAlloc for Allocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if Self::huge(layout.size()) {
            unsafe { huge::alloc(layout) }
        } else {
            unsafe { System.alloc(layout) }
        }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if Self::huge(layout.size()) {
            unsafe { huge::alloc_zeroed(layout) }
        } else {
            unsafe { System.alloc_zeroed(layout) }
        }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if Self::huge(new_size) {
            unsafe { huge::realloc(ptr, layout, new_size) }
        } else {
            unsafe { System.realloc(ptr, layout, new_size) }
        }
    }
}

/// [`Allocator`]'s forms for a buffer of [`HUGE_PAGE`] bytes or more (the caller's contracts
/// of `GlobalAlloc`). Their blocks are freed by `System::dealloc`.
mod huge {
    use super::{advise_huge, HUGE_PAGE};
    use std::alloc::{GlobalAlloc, Layout, System};

    /// A block on a huge-page boundary, advised as huge pages.
    pub(super) unsafe fn alloc(layout: Layout) -> *mut u8 {
        // A larger power-of-two alignment for the same size: refused (null) only where the
        // size rounded up to it would pass isize::MAX.
        let Ok(aligned) = Layout::from_size_align(layout.size(), layout.align().max(HUGE_PAGE))
        else {
            return std::ptr::null_mut();
        };
        let p = unsafe { System.alloc(aligned) };
        if !p.is_null() {
            advise_huge(p, layout.size());
        }
        p
    }

    /// A zeroed block from `calloc` (a fresh mapping is zero already: nothing is touched
    /// here), its whole huge pages advised. Not realigned: zeroing an aligned block would
    /// touch every page of it at once, and the peak would count pages a caller never writes.
    pub(super) unsafe fn alloc_zeroed(layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            advise_huge(p, layout.size());
        }
        p
    }

    /// The block grown or shrunk by `realloc` (glibc moves a mapped block's pages with
    /// `mremap`: the old and new blocks are never resident together), its whole huge pages
    /// advised. A block from [`alloc`] with a larger alignment than the caller's is fine here:
    /// `realloc` keeps any alignment of at most 16.
    pub(super) unsafe fn realloc(ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let new = unsafe { System.realloc(ptr, layout, new_size) };
        if !new.is_null() {
            advise_huge(new, new_size);
        }
        new
    }
}

/// Asks the kernel to back the whole pages of the `len` bytes at `p` with huge pages (the
/// kernel uses them for the 2 MiB-aligned parts not yet touched). A hint: where it is refused
/// (no transparent huge pages) nothing changes.
#[cfg(target_os = "linux")]
fn advise_huge(p: *mut u8, len: usize) {
    const PAGE: usize = 4096;
    let start = (p as usize).next_multiple_of(PAGE);
    let end = (p as usize + len) / PAGE * PAGE;
    if end > start {
        // SAFETY: [start, end) lies within memory this process just allocated; MADV_HUGEPAGE
        // changes no contents, only how pages not yet touched are mapped.
        unsafe {
            libc::madvise(start as *mut libc::c_void, end - start, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge(_: *mut u8, _: usize) {}

/// Makes glibc keep freed buffers for reuse, for the interactive app: buffers up to
/// [`KEEP_MMAP_THRESHOLD`] come from the heap, which grows by [`KEEP_TOP_PAD`] and gives back
/// only more than [`KEEP_TRIM_THRESHOLD`] of free memory at its top. A slider change then
/// writes into the pages the last one freed. The cost is memory held: at most the pad and the
/// trim threshold beyond the app's working set. Call it before other threads start. Whether
/// every setting was taken.
pub fn keep_freed_buffers() -> bool {
    HUGE_PAGES.store(false, Ordering::Relaxed);
    set(&[
        (M_MMAP_THRESHOLD, KEEP_MMAP_THRESHOLD),
        (M_TRIM_THRESHOLD, KEEP_TRIM_THRESHOLD),
        (M_TOP_PAD, KEEP_TOP_PAD),
    ])
}

#[cfg(all(target_os = "linux", target_env = "gnu"))]
use libc::{M_MMAP_THRESHOLD, M_TOP_PAD, M_TRIM_THRESHOLD};
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
const M_MMAP_THRESHOLD: i32 = 0;
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
const M_TRIM_THRESHOLD: i32 = 0;
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
const M_TOP_PAD: i32 = 0;

#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn set(settings: &[(libc::c_int, usize)]) -> bool {
    settings.iter().all(|&(param, value)| {
        let value = libc::c_int::try_from(value).unwrap_or(libc::c_int::MAX);
        // SAFETY: mallopt only sets a tunable of the allocator (it takes the arena lock).
        unsafe { libc::mallopt(param, value) == 1 }
    })
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn set(_: &[(i32, usize)]) -> bool {
    true
}

#[cfg(test)]
mod tests {
    /// glibc takes every setting of both kinds (mallopt returns 1 for each). The app's come
    /// last: this test process then keeps freed buffers, which no test in it measures.
    /// A huge block starts on a huge-page boundary; the zeroed one is zero; growing (also a
    /// block of `huge::alloc`) and shrinking keep the contents; every block is freed by
    /// `System` (as `Allocator` frees).
    #[test]
    fn huge_blocks_are_aligned_zeroed_and_keep_their_contents() {
        use super::{huge, HUGE_PAGE};
        use std::alloc::{GlobalAlloc, Layout, System};
        let size = 3 * HUGE_PAGE + 123;
        let layout = Layout::from_size_align(size, 8).unwrap();
        // SAFETY: every block is used within its size and freed once with its layout.
        unsafe {
            let p = huge::alloc_zeroed(layout);
            assert!(!p.is_null());
            let block = std::slice::from_raw_parts_mut(p, size);
            assert!(block.iter().all(|&b| b == 0));
            for (i, b) in block.iter_mut().enumerate() {
                *b = (i % 251) as u8;
            }
            let q = huge::realloc(p, layout, 5 * HUGE_PAGE);
            assert!(!q.is_null());
            let grown = std::slice::from_raw_parts(q, size);
            assert!(grown.iter().enumerate().all(|(i, &b)| b == (i % 251) as u8));
            let big = Layout::from_size_align(5 * HUGE_PAGE, 8).unwrap();
            let r = System.realloc(q, big, 1000);
            assert!((0..1000).all(|i| *r.add(i) == (i % 251) as u8));
            System.dealloc(r, Layout::from_size_align(1000, 8).unwrap());
            let a = huge::alloc(Layout::from_size_align(HUGE_PAGE, 64).unwrap());
            assert!(!a.is_null() && a as usize % HUGE_PAGE == 0);
            System.dealloc(a, Layout::from_size_align(HUGE_PAGE, 64).unwrap());
            // An aligned block grown by realloc keeps its contents.
            let small = Layout::from_size_align(HUGE_PAGE, 8).unwrap();
            let b = huge::alloc(small);
            assert!(!b.is_null() && b as usize % HUGE_PAGE == 0);
            std::ptr::write_bytes(b, 7, HUGE_PAGE);
            let c = huge::realloc(b, small, 3 * HUGE_PAGE);
            assert!((0..HUGE_PAGE).all(|i| *c.add(i) == 7));
            System.dealloc(c, Layout::from_size_align(3 * HUGE_PAGE, 8).unwrap());
        }
    }

    #[test]
    fn both_settings_are_taken() {
        assert!(super::release_large_buffers());
        assert!(super::keep_freed_buffers());
    }
}
