//! The hot loop of [`crate::MeshMoments::solid`]: the ten sums of the signed
//! tetrahedra over all triangles.
//!
//! Three builds of one sequence of floating-point operations, so all three
//! give the same bits on every machine ([`SolidKernel`] picks one at run
//! time; `KREISEL_KERNEL=portable|avx2|avx512` forces one): a portable
//! scalar loop; an AVX2/FMA loop vectorised across the coordinates of each
//! triangle (a corner is one register `(x, y, z, 0)`, cross products are
//! lane permutations); and the same on AVX-512 with two triangles per
//! register.
//!
//! The sequence, per triangle with corners `a, b, c` (minus the origin) and
//! lanes `i = x, y, z` (`i+1`, `i+2` cyclic), where `fma(x, y, z)` is
//! `x·y + z` rounded once (`f64::mul_add`, `vfmadd`):
//!
//! ```text
//! mᵢ  = fma(bᵢ, cᵢ₊₁, −(bᵢ₊₁·cᵢ))            (b × c)ᵢ₊₂
//! eᵢ  = aᵢ₊₂ · mᵢ
//! dᵢ  = (eᵢ + eᵢ₊₁) + eᵢ₊₂                   a · (b × c), summed from lane i
//! sᵢ  = (aᵢ + bᵢ) + cᵢ
//! qᵢⱼ = fma(sᵢ, sⱼ, fma(aᵢ, aⱼ, fma(bᵢ, bⱼ, cᵢ·cⱼ)))
//! volume += d_x;   firstᵢ = fma(dᵢ, sᵢ, firstᵢ)
//! diagonalᵢ = fma(dᵢ, qᵢᵢ, diagonalᵢ);   offᵢ = fma(dᵢ, qᵢ,ᵢ₊₁, offᵢ)
//! ```
//!
//! Within a block of [`BLOCK`] triangles, the even-numbered triangles
//! (0, 2, 4, …) go into one set of accumulators and the odd-numbered into
//! another (the AVX-512 build's two register halves; the other builds keep
//! two sets too, which also lets the AVX2 build overlap two triangles); a
//! block's sums are `even + odd`, and the blocks' sums are added in block
//! order from zero. Only `+ − ×` and fused multiply-adds, each correctly
//! rounded by IEEE 754, so the bits depend on nothing but this order.
//!
//! The portable build's `f64::mul_add` is one instruction where the target
//! has FMA (aarch64, or x86-64 compiled with `-C target-feature=+fma`);
//! otherwise (the x86-64 baseline) it calls the C library's `fma`, which C99
//! requires to be correctly rounded (same bits) but is a function call, and
//! on a CPU without hardware FMA a software emulation: the portable build
//! then takes ~90 ns per triangle instead of the unfused loop's ~12 ns
//! (BENCHMARKS.md, `cargo bench -p kreisel-inertia --bench kernels`; glibc's
//! software `fma` measured as fast as its FMA one there). x86-64 CPUs
//! without FMA predate AVX2 (before 2013), and any CPU with AVX2 runs the
//! AVX2 build instead.
//!
//! This is the one module with `unsafe`: calling a SIMD build after
//! checking at run time that the CPU supports it, and the masked loads of a
//! vertex's three coordinates, whose indices `TriMesh` checked when it was
//! built.

use glam::DVec3;

use crate::SolidKernel;
use crate::parallel::{map_ranges, threads_for};

/// Triangles summed into one partial sum before it is added to the total,
/// so rounding errors grow like `n/B + B` instead of `n`.
const BLOCK: usize = 512;

/// Ten running sums, with `d = a·(b×c)` and `s = a + b + c` per triangle
/// (corners relative to the origin): Σd, Σd·s (x, y, z), and
/// Σd·(sᵢsⱼ + aᵢaⱼ + bᵢbⱼ + cᵢcⱼ) for xx, yy, zz, xy, xz, yz.
pub(crate) type Sums = [f64; 10];

/// One set of accumulators in the SIMD builds' lane order: the off-diagonal
/// sums are (xy, yz, zx).
#[derive(Clone, Copy, Default)]
struct Lanes {
    volume: f64,
    first: [f64; 3],
    diagonal: [f64; 3],
    off: [f64; 3],
}

impl Lanes {
    /// `self + other`, lane by lane.
    fn add(self, other: Lanes) -> Lanes {
        let add3 = |x: [f64; 3], y: [f64; 3]| [x[0] + y[0], x[1] + y[1], x[2] + y[2]];
        Lanes {
            volume: self.volume + other.volume,
            first: add3(self.first, other.first),
            diagonal: add3(self.diagonal, other.diagonal),
            off: add3(self.off, other.off),
        }
    }

    /// The sums in [`Sums`] order (xy, xz, yz last).
    fn sums(self) -> Sums {
        let (f, d, o) = (self.first, self.diagonal, self.off);
        [
            self.volume,
            f[0],
            f[1],
            f[2],
            d[0],
            d[1],
            d[2],
            o[0],
            o[2],
            o[1],
        ]
    }

    /// Adds one triangle's terms (corners relative to the origin) in the
    /// sequence of the module documentation.
    #[inline(always)]
    fn add_triangle(&mut self, a: [f64; 3], b: [f64; 3], c: [f64; 3]) {
        const NEXT: [usize; 3] = [1, 2, 0];
        const AFTER: [usize; 3] = [2, 0, 1];
        let lanes = [0, 1, 2];
        let m = lanes.map(|i| b[i].mul_add(c[NEXT[i]], -(b[NEXT[i]] * c[i])));
        let e = lanes.map(|i| a[AFTER[i]] * m[i]);
        let d = lanes.map(|i| (e[i] + e[NEXT[i]]) + e[AFTER[i]]);
        let s = lanes.map(|i| (a[i] + b[i]) + c[i]);
        let q = |i: usize, j: usize| {
            s[i].mul_add(s[j], a[i].mul_add(a[j], b[i].mul_add(b[j], c[i] * c[j])))
        };
        self.volume += d[0];
        for i in lanes {
            self.first[i] = d[i].mul_add(s[i], self.first[i]);
            self.diagonal[i] = d[i].mul_add(q(i, i), self.diagonal[i]);
            self.off[i] = d[i].mul_add(q(i, NEXT[i]), self.off[i]);
        }
    }
}

/// The portable build: the sums of one block (at most [`BLOCK`] triangles).
fn block_portable(v: &[DVec3], origin: DVec3, block: &[[u32; 3]]) -> Sums {
    let corner = |i: u32| (v[i as usize] - origin).to_array();
    let (mut even, mut odd) = (Lanes::default(), Lanes::default());
    for pair in block.chunks(2) {
        let [i, j, k] = pair[0];
        even.add_triangle(corner(i), corner(j), corner(k));
        if let Some(&[i, j, k]) = pair.get(1) {
            odd.add_triangle(corner(i), corner(j), corner(k));
        }
    }
    even.add(odd).sums()
}

#[cfg(target_arch = "x86_64")]
mod avx2;

#[cfg(target_arch = "x86_64")]
mod avx512;

/// The ten sums of a mesh's triangles about `origin` (every index must be
/// in range for `v`; [`crate::TriMesh`] guarantees it) by the build
/// `kernel` (the portable one if this CPU cannot run it), on the machine's
/// cores from [`crate::parallel::PARALLEL_MIN`] triangles.
///
/// The same bits on any number of threads: each block of [`BLOCK`]
/// triangles is summed alone, and the blocks' sums are added in block order.
pub(crate) fn solid_sums(
    v: &[DVec3],
    origin: DVec3,
    triangles: &[[u32; 3]],
    kernel: SolidKernel,
) -> Sums {
    solid_sums_on(v, origin, triangles, threads_for(triangles.len()), kernel)
}

/// [`solid_sums`] on at most `threads` threads.
fn solid_sums_on(
    v: &[DVec3],
    origin: DVec3,
    triangles: &[[u32; 3]],
    threads: usize,
    kernel: SolidKernel,
) -> Sums {
    let kernel = kernel.check().unwrap_or(SolidKernel::Portable);
    let partials = map_ranges(triangles.len(), threads, BLOCK, |r| {
        triangles[r]
            .chunks(BLOCK)
            .map(|block| block_sums(v, origin, block, kernel))
            .collect::<Vec<Sums>>()
    });
    add_in_order(partials.iter().flatten())
}

/// Block sums added in the order given, starting from zero.
pub(crate) fn add_in_order<'a>(partials: impl Iterator<Item = &'a Sums>) -> Sums {
    let mut total = [0.0; 10];
    for part in partials {
        for (t, p) in total.iter_mut().zip(part) {
            *t += p;
        }
    }
    total
}

/// The sums of one block (at most [`BLOCK`] triangles) by `kernel`, which
/// this CPU runs ([`solid_sums_on`] checked it).
#[allow(unsafe_code)]
fn block_sums(v: &[DVec3], origin: DVec3, block: &[[u32; 3]], kernel: SolidKernel) -> Sums {
    debug_assert!(block.len() <= BLOCK && kernel.is_supported());
    match kernel {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: `avx512::block` needs only AVX-512F/VL and FMA, which the
        // CPU has (`kernel.check()` in `solid_sums_on`).
        SolidKernel::Avx512 => unsafe { avx512::block(v, origin, block) },
        #[cfg(target_arch = "x86_64")]
        // SAFETY: `avx2::block` needs only AVX2 and FMA, which the CPU has
        // (`kernel.check()` in `solid_sums_on`).
        SolidKernel::Avx2 => unsafe { avx2::block(v, origin, block) },
        _ => block_portable(v, origin, block),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Irrational-looking vertices (round-off in every operation), `n`
    /// triangles over them, and an origin off the vertex mean.
    fn scattered(n: u32) -> (Vec<DVec3>, Vec<[u32; 3]>, DVec3) {
        let v: Vec<DVec3> = (0..3001)
            .map(|i| {
                let t = f64::from(i);
                DVec3::new((0.37 * t).sin(), (1.3 * t).cos(), (0.71 * t).sin() * 2.0)
            })
            .collect();
        let tris = (0..n)
            .map(|i| [i % 3001, (7 * i + 1) % 3001, (13 * i + 5) % 3001])
            .collect();
        (v, tris, DVec3::new(0.1, -0.2, 0.3))
    }

    /// Every build this CPU runs gives the portable build's bits, for
    /// triangle counts around the block size and the AVX-512 pairs (odd
    /// tails), on every thread count.
    #[test]
    fn every_build_gives_the_portable_bits() {
        for n in [0, 1, 2, 3, 37, 511, 512, 513, 1023, 1025, 5000] {
            let (v, tris, origin) = scattered(n);
            let portable = solid_sums_on(&v, origin, &tris, 1, SolidKernel::Portable);
            for kernel in SolidKernel::supported() {
                for threads in [1, 3] {
                    let sums = solid_sums_on(&v, origin, &tris, threads, kernel);
                    assert_eq!(
                        sums.map(f64::to_bits),
                        portable.map(f64::to_bits),
                        "{kernel}, {n} triangles, {threads} threads"
                    );
                }
            }
        }
    }

    /// The builds match a direct per-triangle sum (the formulas, unfused,
    /// one accumulator) to rounding, the last vertex included (the masked
    /// loads).
    #[test]
    fn builds_agree_with_direct_sum() {
        let (v, tris, origin) = scattered(1037);
        let mut direct = [0.0; 10];
        for &[i, j, k] in &tris {
            let (a, b, c) = (
                v[i as usize] - origin,
                v[j as usize] - origin,
                v[k as usize] - origin,
            );
            let d = a.dot(b.cross(c));
            let s = a + b + c;
            let q = |i: usize, j: usize| s[i] * s[j] + a[i] * a[j] + b[i] * b[j] + c[i] * c[j];
            let t = [
                1.0,
                s.x,
                s.y,
                s.z,
                q(0, 0),
                q(1, 1),
                q(2, 2),
                q(0, 1),
                q(0, 2),
                q(1, 2),
            ];
            for (acc, t) in direct.iter_mut().zip(t) {
                *acc += d * t;
            }
        }
        let last = [[3000, 0, 1]];
        let scale: f64 = direct.iter().map(|x| x.abs()).fold(1.0, f64::max);
        for kernel in SolidKernel::supported() {
            let sums = solid_sums_on(&v, origin, &tris, 1, kernel);
            for (x, y) in sums.iter().zip(&direct) {
                assert!((x - y).abs() < 1e-13 * scale, "{kernel}: {x} vs {y}");
            }
            let edge = solid_sums_on(&v, origin, &last, 1, kernel);
            let portable = solid_sums_on(&v, origin, &last, 1, SolidKernel::Portable);
            assert_eq!(edge.map(f64::to_bits), portable.map(f64::to_bits));
        }
    }

    /// An axis-aligned box with integer corners (no round-off: every
    /// product and sum is exact) gives the exact sums in every build:
    /// Σd = 6V, Σd·s = 24 V c, Σd·(sₓ² + …) = 120 ∫x² dV.
    #[test]
    fn integer_box_is_exact_in_every_build() {
        // [0, 2] × [0, 4] × [0, 6] about the origin (0, 0, 0).
        let (x, y, z) = (2.0, 4.0, 6.0);
        let v: Vec<DVec3> = (0..8)
            .map(|k| {
                DVec3::new(
                    x * f64::from(k & 1),
                    y * f64::from((k >> 1) & 1),
                    z * f64::from((k >> 2) & 1),
                )
            })
            .collect();
        #[rustfmt::skip]
        let tris = vec![
            [0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], // z = 0, z = z
            [0, 1, 4], [1, 5, 4], [2, 6, 3], [3, 6, 7], // y = 0, y = y
            [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5], // x = 0, x = x
        ];
        let volume = x * y * z;
        // ∫x² = x³yz/3, ∫xy = x²y²z/4
        let expected = [
            6.0 * volume,
            24.0 * volume * x / 2.0,
            24.0 * volume * y / 2.0,
            24.0 * volume * z / 2.0,
            120.0 * x * x * volume / 3.0,
            120.0 * y * y * volume / 3.0,
            120.0 * z * z * volume / 3.0,
            120.0 * x * y * volume / 4.0,
            120.0 * x * z * volume / 4.0,
            120.0 * y * z * volume / 4.0,
        ];
        for kernel in SolidKernel::supported() {
            let sums = solid_sums_on(&v, DVec3::ZERO, &tris, 1, kernel);
            assert_eq!(sums, expected, "{kernel}");
        }
    }
}
