//! Variance-minimising median cut: fills the palette slots left after the
//! exact seed colours with colours for shading ramps and anti-aliased edges.

use super::palette::{cell_sums, pack};

/// A histogram cell used by the median cut: mean colour and sample count.
#[derive(Debug, Clone, Copy)]
struct Entry {
    c: [f64; 3],
    w: f64,
}

/// A box of the median cut: a range of `entries` plus its statistics.
#[derive(Debug, Clone, Copy)]
struct CutBox {
    start: usize,
    end: usize,
    mean: [f64; 3],
    /// Weighted sum of squared errors about the mean, per axis.
    sse: [f64; 3],
}

impl CutBox {
    fn new(entries: &[Entry], start: usize, end: usize) -> CutBox {
        let mut w = 0.0;
        let mut s = [0.0; 3];
        let mut s2 = [0.0; 3];
        for e in &entries[start..end] {
            w += e.w;
            for k in 0..3 {
                s[k] += e.w * e.c[k];
                s2[k] += e.w * e.c[k] * e.c[k];
            }
        }
        let mut mean = [0.0; 3];
        let mut sse = [0.0; 3];
        if w > 0.0 {
            for k in 0..3 {
                mean[k] = s[k] / w;
                sse[k] = (s2[k] - s[k] * s[k] / w).max(0.0);
            }
        }
        CutBox {
            start,
            end,
            mean,
            sse,
        }
    }

    fn total_sse(&self) -> f64 {
        self.sse.iter().sum()
    }
}

/// Variance-minimising median cut of the (non-seed) colours into at most `budget` colours.
pub(super) fn median_cut(distinct: &[(u32, u32)], budget: usize) -> Vec<u32> {
    // Work on 15-bit cells (mean colour + weight): this bounds the work, and
    // the lookup table cannot tell colours within one cell apart anyway.
    let mut entries: Vec<Entry> = cell_sums(distinct)
        .iter()
        .filter(|a| a[0] > 0)
        .map(|a| {
            let n = a[0] as f64;
            Entry {
                c: [a[1] as f64 / n, a[2] as f64 / n, a[3] as f64 / n],
                w: n,
            }
        })
        .collect();
    if entries.is_empty() || budget == 0 {
        return Vec::new();
    }
    let len = entries.len();
    let mut boxes = vec![CutBox::new(&entries, 0, len)];
    while boxes.len() < budget {
        let pick = boxes
            .iter()
            .enumerate()
            .filter(|(_, b)| b.end - b.start >= 2 && b.total_sse() > 0.0)
            .max_by(|a, b| a.1.total_sse().total_cmp(&b.1.total_sse()))
            .map(|(i, _)| i);
        let Some(i) = pick else { break };
        let b = boxes[i];
        let axis = (0..3)
            .max_by(|&x, &y| b.sse[x].total_cmp(&b.sse[y]))
            .unwrap_or(0);
        let slice = &mut entries[b.start..b.end];
        slice.sort_unstable_by(|p, q| p.c[axis].total_cmp(&q.c[axis]));
        // Split where the summed squared error along `axis` is smallest.
        let (mut tw, mut ts, mut ts2) = (0.0, 0.0, 0.0);
        for e in slice.iter() {
            tw += e.w;
            ts += e.w * e.c[axis];
            ts2 += e.w * e.c[axis] * e.c[axis];
        }
        let (mut lw, mut ls, mut ls2) = (0.0, 0.0, 0.0);
        let mut best = (f64::INFINITY, 1usize);
        for (k, e) in slice.iter().enumerate().take(slice.len() - 1) {
            lw += e.w;
            ls += e.w * e.c[axis];
            ls2 += e.w * e.c[axis] * e.c[axis];
            let (rw, rs, rs2) = (tw - lw, ts - ls, ts2 - ls2);
            let cost = (ls2 - ls * ls / lw) + (rs2 - rs * rs / rw.max(f64::MIN_POSITIVE));
            if cost < best.0 {
                best = (cost, k + 1);
            }
        }
        let mid = b.start + best.1;
        boxes[i] = CutBox::new(&entries, b.start, mid);
        boxes.push(CutBox::new(&entries, mid, b.end));
    }
    boxes.iter().map(|b| pack(b.mean)).collect()
}
