//! The hot loop of [`crate::MeshMoments::solid`]: the ten sums of the signed
//! tetrahedra over all triangles.
//!
//! Three builds of the same formulas: a portable scalar loop; an AVX2/FMA
//! loop vectorised across the coordinates of each triangle (a corner is one
//! register `(x, y, z, 0)`, cross products are lane permutations, four
//! registers accumulate the ten sums); and the same on AVX-512 with two
//! triangles per register. This is the one module with `unsafe`: calling a
//! SIMD build after checking at run time that the CPU supports it, and the
//! masked loads of a vertex's three coordinates, whose indices `TriMesh`
//! checked when it was built. Measured in BENCHMARKS.md (`cargo bench
//! --bench inertia`): 13.3 ns per triangle scalar, ≈ 6 ns AVX2, ≈ 5 ns
//! AVX-512.

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

/// One triangle's ten terms before weighting by `d`, and `d` itself.
#[inline(always)]
fn terms(a: DVec3, b: DVec3, c: DVec3) -> (f64, [f64; 9]) {
    let d = a.dot(b.cross(c));
    let s = a + b + c;
    let q = |i: usize, j: usize| s[i] * s[j] + a[i] * a[j] + b[i] * b[j] + c[i] * c[j];
    (
        d,
        [
            s.x,
            s.y,
            s.z,
            q(0, 0),
            q(1, 1),
            q(2, 2),
            q(0, 1),
            q(0, 2),
            q(1, 2),
        ],
    )
}

/// The portable build: one triangle at a time.
fn sums_scalar(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]]) -> Sums {
    let mut total = [0.0; 10];
    for block in triangles.chunks(BLOCK) {
        let mut acc = [0.0; 10];
        for &[i, j, k] in block {
            let (d, t) = terms(
                v[i as usize] - origin,
                v[j as usize] - origin,
                v[k as usize] - origin,
            );
            acc[0] += d;
            for (a, t) in acc[1..].iter_mut().zip(t) {
                *a += d * t;
            }
        }
        for (t, a) in total.iter_mut().zip(acc) {
            *t += a;
        }
    }
    total
}

#[cfg(target_arch = "x86_64")]
mod avx2 {
    //! AVX2 + FMA. The only `unsafe` besides the dispatch: a masked load
    //! of a vertex's three coordinates, whose index `TriMesh` has checked.

    #![allow(unsafe_code)]

    use core::arch::x86_64::*;

    use super::{BLOCK, Sums};
    use glam::DVec3;

    /// Vertex `i` minus the origin as `(x, y, z, 0)`: one masked load of
    /// the three coordinates (it never touches the bytes after them).
    ///
    /// # Safety
    /// `3i + 3 ≤ flat.len()`: every index of a [`crate::TriMesh`] is in
    /// range (checked when it is built).
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn corner(flat: &[f64], origin: __m256d, i: u32) -> __m256d {
        debug_assert!(3 * i as usize + 3 <= flat.len());
        let mask = _mm256_set_epi64x(0, -1, -1, -1);
        // SAFETY: lanes 0..3 read flat[3i..3i+3], in bounds by the caller's
        // promise; the masked-off lane 3 is not read.
        let p = unsafe { _mm256_maskload_pd(flat.as_ptr().add(3 * i as usize), mask) };
        _mm256_sub_pd(p, origin)
    }

    /// Lanes `(y, z, x, ·)`.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    fn yzx(a: __m256d) -> __m256d {
        _mm256_permute4x64_pd::<0b11_00_10_01>(a)
    }

    /// Lanes `(z, x, y, ·)`.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    fn zxy(a: __m256d) -> __m256d {
        _mm256_permute4x64_pd::<0b11_01_00_10>(a)
    }

    /// Lane `k` of a register.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    fn lane(a: __m256d, k: usize) -> f64 {
        let lo = _mm256_castpd256_pd128(a);
        let hi = _mm256_extractf128_pd::<1>(a);
        match k {
            0 => _mm_cvtsd_f64(lo),
            1 => _mm_cvtsd_f64(_mm_unpackhi_pd(lo, lo)),
            _ => _mm_cvtsd_f64(hi),
        }
    }

    /// The AVX2 build of [`super::sums_scalar`].
    #[target_feature(enable = "avx2,fma")]
    pub(super) fn sums(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]]) -> Sums {
        let flat: &[f64] = bytemuck::cast_slice(v);
        let o = _mm256_set_pd(0.0, origin.z, origin.y, origin.x);
        let mut total = [0.0; 10];
        for block in triangles.chunks(BLOCK) {
            let zero = _mm256_setzero_pd();
            let (mut volume, mut first, mut diagonal, mut off) = (zero, zero, zero, zero);
            for &[i, j, k] in block {
                // SAFETY: the indices come from a TriMesh, so they are in range.
                let (a, b, c) =
                    unsafe { (corner(flat, o, i), corner(flat, o, j), corner(flat, o, k)) };
                let (a1, b1, c1) = (yzx(a), yzx(b), yzx(c));
                // m = b ∘ c.yzx − b.yzx ∘ c = (b × c).zxy, so
                // d = a · (b × c) = Σᵢ (a.zxy ∘ m)ᵢ, summed into every lane
                // by adding its two rotations (no extract or broadcast).
                let m = _mm256_fmsub_pd(b, c1, _mm256_mul_pd(b1, c));
                let am = _mm256_mul_pd(zxy(a), m);
                let dd = _mm256_add_pd(_mm256_add_pd(am, yzx(am)), zxy(am));
                let s = _mm256_add_pd(_mm256_add_pd(a, b), c);
                // (sᵢsᵢ + …) and (sᵢsⱼ + …) with j = i + 1 (mod 3)
                let sq = _mm256_fmadd_pd(
                    s,
                    s,
                    _mm256_fmadd_pd(a, a, _mm256_fmadd_pd(b, b, _mm256_mul_pd(c, c))),
                );
                // s.yzx from the rotated corners: additions instead of a permutation.
                let s1 = _mm256_add_pd(_mm256_add_pd(a1, b1), c1);
                let cross = _mm256_fmadd_pd(
                    s,
                    s1,
                    _mm256_fmadd_pd(a, a1, _mm256_fmadd_pd(b, b1, _mm256_mul_pd(c, c1))),
                );
                volume = _mm256_add_pd(volume, dd);
                first = _mm256_fmadd_pd(dd, s, first);
                diagonal = _mm256_fmadd_pd(dd, sq, diagonal);
                off = _mm256_fmadd_pd(dd, cross, off);
            }
            // `off` holds (xy, yz, zx); Sums wants xy, xz, yz.
            let part = [
                lane(volume, 0),
                lane(first, 0),
                lane(first, 1),
                lane(first, 2),
                lane(diagonal, 0),
                lane(diagonal, 1),
                lane(diagonal, 2),
                lane(off, 0),
                lane(off, 2),
                lane(off, 1),
            ];
            for (t, p) in total.iter_mut().zip(part) {
                *t += p;
            }
        }
        total
    }
}

#[cfg(target_arch = "x86_64")]
mod avx512 {
    //! AVX-512: the AVX2 loop with two triangles per 512-bit register (one
    //! per 256-bit half; the in-lane permutations work on both halves).

    #![allow(unsafe_code)]

    use core::arch::x86_64::*;

    use super::{BLOCK, Sums};
    use glam::DVec3;

    /// Vertices `i` and `j` minus the origin as `(x, y, z, 0 | x, y, z, 0)`.
    ///
    /// # Safety
    /// `3i + 3 ≤ flat.len()` and `3j + 3 ≤ flat.len()` (indices of a
    /// [`crate::TriMesh`] are checked when it is built).
    #[inline]
    #[target_feature(enable = "avx512f,avx512vl,fma")]
    unsafe fn corners(flat: &[f64], origin: __m512d, i: u32, j: u32) -> __m512d {
        debug_assert!(3 * i.max(j) as usize + 3 <= flat.len());
        // SAFETY: three in-bounds coordinates each (the caller's promise);
        // the masked-off fourth lanes are not read.
        let (lo, hi) = unsafe {
            (
                _mm256_maskz_loadu_pd(0b0111, flat.as_ptr().add(3 * i as usize)),
                _mm256_maskz_loadu_pd(0b0111, flat.as_ptr().add(3 * j as usize)),
            )
        };
        _mm512_sub_pd(
            _mm512_insertf64x4::<1>(_mm512_castpd256_pd512(lo), hi),
            origin,
        )
    }

    /// Lanes `(y, z, x, ·)` in both halves.
    #[inline]
    #[target_feature(enable = "avx512f,avx512vl,fma")]
    fn yzx(a: __m512d) -> __m512d {
        _mm512_permutex_pd::<0b11_00_10_01>(a)
    }

    /// Lanes `(z, x, y, ·)` in both halves.
    #[inline]
    #[target_feature(enable = "avx512f,avx512vl,fma")]
    fn zxy(a: __m512d) -> __m512d {
        _mm512_permutex_pd::<0b11_01_00_10>(a)
    }

    /// Lane `k` (0, 1 or 2) summed over both halves.
    #[inline]
    #[target_feature(enable = "avx512f,avx512vl,fma")]
    fn lane(a: __m512d, k: usize) -> f64 {
        let h = _mm256_add_pd(_mm512_castpd512_pd256(a), _mm512_extractf64x4_pd::<1>(a));
        let lo = _mm256_castpd256_pd128(h);
        match k {
            0 => _mm_cvtsd_f64(lo),
            1 => _mm_cvtsd_f64(_mm_unpackhi_pd(lo, lo)),
            _ => _mm_cvtsd_f64(_mm256_extractf128_pd::<1>(h)),
        }
    }

    /// The AVX-512 build of [`super::sums_scalar`].
    #[target_feature(enable = "avx512f,avx512vl,fma")]
    pub(super) fn sums(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]]) -> Sums {
        let flat: &[f64] = bytemuck::cast_slice(v);
        let o = _mm512_set_pd(
            0.0, origin.z, origin.y, origin.x, 0.0, origin.z, origin.y, origin.x,
        );
        let mut total = [0.0; 10];
        for block in triangles.chunks(BLOCK) {
            let zero = _mm512_setzero_pd();
            let (mut volume, mut first, mut diagonal, mut off) = (zero, zero, zero, zero);
            let mut pairs = block.chunks_exact(2);
            let rest = pairs.remainder();
            // An odd last triangle is paired with [0, 0, 0], whose d is 0.
            let tail = rest.first().map(|&t| [t, [0; 3]]);
            for pair in pairs.by_ref().map(|p| [p[0], p[1]]).chain(tail) {
                let [[i0, j0, k0], [i1, j1, k1]] = pair;
                // SAFETY: the indices come from a TriMesh, so they are in range.
                let (a, b, c) = unsafe {
                    (
                        corners(flat, o, i0, i1),
                        corners(flat, o, j0, j1),
                        corners(flat, o, k0, k1),
                    )
                };
                let (a1, b1, c1) = (yzx(a), yzx(b), yzx(c));
                let m = _mm512_fmsub_pd(b, c1, _mm512_mul_pd(b1, c));
                let am = _mm512_mul_pd(zxy(a), m);
                let dd = _mm512_add_pd(_mm512_add_pd(am, yzx(am)), zxy(am));
                let s = _mm512_add_pd(_mm512_add_pd(a, b), c);
                let sq = _mm512_fmadd_pd(
                    s,
                    s,
                    _mm512_fmadd_pd(a, a, _mm512_fmadd_pd(b, b, _mm512_mul_pd(c, c))),
                );
                let s1 = yzx(s);
                let cross = _mm512_fmadd_pd(
                    s,
                    s1,
                    _mm512_fmadd_pd(a, a1, _mm512_fmadd_pd(b, b1, _mm512_mul_pd(c, c1))),
                );
                volume = _mm512_add_pd(volume, dd);
                first = _mm512_fmadd_pd(dd, s, first);
                diagonal = _mm512_fmadd_pd(dd, sq, diagonal);
                off = _mm512_fmadd_pd(dd, cross, off);
            }
            let part = [
                lane(volume, 0),
                lane(first, 0),
                lane(first, 1),
                lane(first, 2),
                lane(diagonal, 0),
                lane(diagonal, 1),
                lane(diagonal, 2),
                lane(off, 0),
                lane(off, 2),
                lane(off, 1),
            ];
            for (t, p) in total.iter_mut().zip(part) {
                *t += p;
            }
        }
        total
    }
}

/// The ten sums of a mesh's triangles about `origin` (every index must be
/// in range for `v`; [`crate::TriMesh`] guarantees it), on the machine's
/// cores from [`crate::parallel::PARALLEL_MIN`] triangles.
pub(crate) fn solid_sums(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]], kernel: SolidKernel) -> Sums {
    solid_sums_on(v, origin, triangles, threads_for(triangles.len()), kernel)
}

/// [`solid_sums`] on at most `threads` threads.
fn solid_sums_on(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]], threads: usize, kernel: SolidKernel) -> Sums {
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

/// The sums of one block on this thread, in the build `kernel`, or in the
/// portable one if the CPU lacks its features.
#[allow(unsafe_code)]
fn block_sums(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]], kernel: SolidKernel) -> Sums {
    #[cfg(target_arch = "x86_64")]
    match kernel {
        SolidKernel::Avx512 if kernel.is_supported() => {
            // SAFETY: `avx512::sums` needs only AVX-512F/VL and FMA, which
            // the CPU has (checked just above).
            return unsafe { avx512::sums(v, origin, triangles) };
        }
        SolidKernel::Avx2 if kernel.is_supported() => {
            // SAFETY: `avx2::sums` needs only AVX2 and FMA, which the CPU
            // has (checked just above).
            return unsafe { avx2::sums(v, origin, triangles) };
        }
        _ => {}
    }
    let _ = kernel;
    sums_scalar(v, origin, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both builds match a direct per-triangle sum, the last vertex included
    /// (the padded load).
    #[test]
    fn builds_agree_with_direct_sum() {
        let v: Vec<DVec3> = (0..40)
            .map(|i| {
                let t = i as f64;
                DVec3::new(t.sin(), (1.3 * t).cos(), (0.7 * t).sin() * 2.0)
            })
            .collect();
        let tris: Vec<[u32; 3]> = (0..37u32).map(|i| [i, (i + 1) % 40, 39 - i % 5]).collect();
        let origin = DVec3::new(0.1, -0.2, 0.3);
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
        let mut builds = vec![
            sums_scalar(&v, origin, &tris),
            solid_sums(&v, origin, &tris, SolidKernel::active()),
        ];
        #[cfg(target_arch = "x86_64")]
        #[allow(unsafe_code)]
        {
            use std::arch::is_x86_feature_detected as has;
            if has!("avx2") && has!("fma") {
                // SAFETY: the features were just checked.
                builds.push(unsafe { avx2::sums(&v, origin, &tris) });
            }
            if has!("avx512f") && has!("avx512vl") && has!("fma") {
                // SAFETY: the features were just checked.
                builds.push(unsafe { avx512::sums(&v, origin, &tris) });
            }
        }
        for fast in builds {
            for (x, y) in fast.iter().zip(&direct) {
                assert!((x - y).abs() < 1e-13 * y.abs().max(1.0), "{x} vs {y}");
            }
        }
    }

    /// Any number of threads gives the bits of one thread summing every
    /// block in order (the build of the sums before they were parallel).
    #[test]
    fn sums_do_not_depend_on_the_thread_count() {
        let v: Vec<DVec3> = (0..3001)
            .map(|i| {
                let t = f64::from(i);
                DVec3::new((0.37 * t).sin(), (1.3 * t).cos(), (0.71 * t).sin() * 2.0)
            })
            .collect();
        let tris: Vec<[u32; 3]> = (0..5000u32)
            .map(|i| [i % 3001, (7 * i + 1) % 3001, (13 * i + 5) % 3001])
            .collect();
        let origin = DVec3::new(0.1, -0.2, 0.3);
        let one = block_sums(&v, origin, &tris, SolidKernel::fastest());
        for threads in [1, 2, 3, 4, 7, 64] {
            let many = solid_sums_on(&v, origin, &tris, threads, SolidKernel::fastest());
            assert_eq!(many.map(f64::to_bits), one.map(f64::to_bits), "{threads}");
        }
    }
}
