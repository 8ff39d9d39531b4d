//! Deterministic data parallelism over the machine's cores: a job of `n`
//! items is cut into contiguous ranges, one per thread
//! (`std::thread::scope`), and the results come back in range order, so a
//! caller that combines them in that order gets the same bits on 1 or N
//! threads. The callers keep their sums in fixed blocks (e.g. 512 triangles
//! per partial sum) and cut ranges only at block boundaries, so each block's
//! partial sum is the same whatever the thread count, and the partials are
//! added in block order on the calling thread.
//!
//! No new dependency: `rayon` would schedule the same few ranges, and the
//! phases here are a handful of calls of ~10 ms each at 10⁶ triangles,
//! where starting two scoped threads costs ~20 µs.

use std::ops::Range;

/// Items below which a job stays on the calling thread (starting a thread
/// costs more than it saves).
pub(crate) const PARALLEL_MIN: usize = 1 << 15;

/// Threads at most (the machine's cores beyond this gain little on the
/// memory-bound phases).
const MAX_THREADS: usize = 8;

/// Threads for a job of `n` items: 1 below [`PARALLEL_MIN`], else the
/// environment variable `KREISEL_THREADS` if it is a positive number (as
/// `RAYON_NUM_THREADS`: e.g. `1` on a machine whose cores are busy with
/// other work, where threads only add their overhead), else the machine's
/// available parallelism, at most [`MAX_THREADS`].
pub(crate) fn threads_for(n: usize) -> usize {
    if n < PARALLEL_MIN {
        return 1;
    }
    static THREADS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *THREADS.get_or_init(|| {
        let machine = std::thread::available_parallelism().map_or(1, |p| p.get());
        std::env::var("KREISEL_THREADS")
            .ok()
            .and_then(|v| v.trim().parse::<usize>().ok())
            .filter(|&t| t > 0)
            .unwrap_or(machine)
            .min(MAX_THREADS)
    })
}

/// `0..n` cut into at most `parts` contiguous, non-empty ranges in order,
/// every cut at a multiple of `align` (≥ 1); one empty range when `n = 0`.
pub(crate) fn ranges(n: usize, parts: usize, align: usize) -> Vec<Range<usize>> {
    let align = align.max(1);
    let units = n.div_ceil(align);
    let parts = parts.clamp(1, units.max(1));
    (0..parts)
        .map(|p| {
            let cut = |q: usize| (units * q / parts * align).min(n);
            cut(p)..cut(p + 1)
        })
        .filter(|r| !r.is_empty() || n == 0)
        .collect()
}

/// `f` of each of [`ranges`]`(n, parts, align)`, each range on its own
/// thread (the first on the calling thread), in range order.
pub(crate) fn map_ranges<T: Send>(
    n: usize,
    parts: usize,
    align: usize,
    f: impl Fn(Range<usize>) -> T + Sync,
) -> Vec<T> {
    let mut cuts = ranges(n, parts, align).into_iter();
    let first = cuts.next().unwrap_or(0..0);
    if cuts.len() == 0 {
        return vec![f(first)];
    }
    std::thread::scope(|scope| {
        let f = &f;
        let others: Vec<_> = cuts.map(|r| scope.spawn(move || f(r))).collect();
        let mut out = vec![f(first)];
        // A panic on a worker is a bug here as on the calling thread:
        // pass it on rather than lose a range.
        out.extend(
            others
                .into_iter()
                .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))),
        );
        out
    })
}

/// `f` of each of [`ranges`]`(n, parts, align)` with its own part of
/// `items` (`items[range]`, mutable), each on its own thread, in range order.
pub(crate) fn map_slices<I: Send, T: Send>(
    items: &mut [I],
    parts: usize,
    align: usize,
    f: impl Fn(usize, &mut [I]) -> T + Sync,
) -> Vec<T> {
    let cuts = ranges(items.len(), parts, align);
    map_pieces(items, &cuts, |p, piece| f(cuts[p].start, piece))
}

/// `f(p, &mut items[cuts[p]])` for each of the contiguous ranges `cuts`
/// (in order, from 0, covering `items`), each on its own thread (the first
/// on the calling thread), in range order.
///
/// # Panics
/// If `cuts` do not cover `items` contiguously from 0.
pub(crate) fn map_pieces<I: Send, T: Send>(
    items: &mut [I],
    cuts: &[Range<usize>],
    f: impl Fn(usize, &mut [I]) -> T + Sync,
) -> Vec<T> {
    let mut pieces = Vec::with_capacity(cuts.len());
    let mut rest = items;
    let mut at = 0;
    for r in cuts {
        assert_eq!(r.start, at, "contiguous cuts");
        let (head, tail) = rest.split_at_mut(r.len());
        pieces.push(head);
        rest = tail;
        at = r.end;
    }
    assert!(rest.is_empty(), "cuts cover the items");
    let mut pieces = pieces.into_iter().enumerate();
    let Some((_, first)) = pieces.next() else {
        return Vec::new();
    };
    if pieces.len() == 0 {
        return vec![f(0, first)];
    }
    std::thread::scope(|scope| {
        let f = &f;
        let others: Vec<_> = pieces
            .map(|(p, piece)| scope.spawn(move || f(p, piece)))
            .collect();
        let mut out = vec![f(0, first)];
        out.extend(
            others
                .into_iter()
                .map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))),
        );
        out
    })
}

/// Whether `test` holds for any of `items`, on the machine's cores for
/// large slices.
pub(crate) fn any<I: Sync>(items: &[I], test: impl Fn(&I) -> bool + Sync) -> bool {
    let parts = threads_for(items.len());
    map_ranges(items.len(), parts, 1, |r| items[r].iter().any(&test))
        .into_iter()
        .any(|found| found)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_cover_in_order_at_aligned_cuts() {
        for n in [0, 1, 5, 511, 512, 513, 1000, 4096, 100_000] {
            for parts in 1..6 {
                for align in [1, 7, 512] {
                    let r = ranges(n, parts, align);
                    assert!(r.len() <= parts.max(1));
                    assert_eq!(r[0].start, 0);
                    assert_eq!(r.last().map(|r| r.end), Some(n));
                    for w in r.windows(2) {
                        assert_eq!(w[0].end, w[1].start);
                        assert_eq!(w[0].end % align, 0, "{n} {parts} {align}");
                        assert!(!w[1].is_empty());
                    }
                }
            }
        }
    }

    #[test]
    fn results_come_back_in_range_order() {
        let sums = map_ranges(10_000, 4, 100, |r| r.clone().sum::<usize>());
        assert_eq!(sums.len(), 4);
        assert_eq!(sums.iter().sum::<usize>(), (0..10_000).sum::<usize>());
        let mut items: Vec<usize> = (0..1000).collect();
        let starts = map_slices(&mut items, 3, 10, |start, piece| {
            piece.iter_mut().for_each(|x| *x *= 2);
            (start, piece.len())
        });
        assert_eq!(starts.iter().map(|s| s.1).sum::<usize>(), 1000);
        assert!(starts.windows(2).all(|w| w[0].0 + w[0].1 == w[1].0));
        assert!(items.iter().enumerate().all(|(i, &x)| x == 2 * i));
        let big: Vec<usize> = (0..PARALLEL_MIN * 3).collect();
        assert!(any(&big, |&x| x == PARALLEL_MIN * 3 - 1));
        assert!(!any(&big, |&x| x == PARALLEL_MIN * 3));
    }
}
