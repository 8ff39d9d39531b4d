//! AVX2 + FMA: one triangle per 256-bit register `(x, y, z, 0)`, the
//! even and odd triangles of a block in two sets of four accumulators.

#![allow(unsafe_code)]

use core::arch::x86_64::*;

use super::Sums;
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

/// Lanes 0, 1, 2 of a register.
#[inline]
#[target_feature(enable = "avx2,fma")]
fn lanes(a: __m256d) -> [f64; 3] {
    let mut out = [0.0; 4];
    // SAFETY: `out` holds four f64 (an unaligned store).
    unsafe { _mm256_storeu_pd(out.as_mut_ptr(), a) };
    [out[0], out[1], out[2]]
}

/// Accumulators: volume (lane 0), first, diagonal and off-diagonal
/// (xy, yz, zx).
type Acc = [__m256d; 4];

/// Adds triangle `[i, j, k]` to `acc` (the sequence of the module
/// documentation of `solid_kernel`).
///
/// # Safety
/// The indices are in range for `flat` (see [`corner`]).
#[inline]
#[target_feature(enable = "avx2,fma")]
unsafe fn add_triangle(acc: &mut Acc, flat: &[f64], o: __m256d, [i, j, k]: [u32; 3]) {
    // SAFETY: the caller's promise.
    let (a, b, c) = unsafe { (corner(flat, o, i), corner(flat, o, j), corner(flat, o, k)) };
    let (a1, b1, c1) = (yzx(a), yzx(b), yzx(c));
    // m = b ∘ c.yzx − b.yzx ∘ c = (b × c).zxy, so
    // d = a · (b × c) = Σᵢ (a.zxy ∘ m)ᵢ, summed into every lane
    // by adding its two rotations (no extract or broadcast).
    let m = _mm256_fmsub_pd(b, c1, _mm256_mul_pd(b1, c));
    let e = _mm256_mul_pd(zxy(a), m);
    let d = _mm256_add_pd(_mm256_add_pd(e, yzx(e)), zxy(e));
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
    acc[0] = _mm256_add_pd(acc[0], d);
    acc[1] = _mm256_fmadd_pd(d, s, acc[1]);
    acc[2] = _mm256_fmadd_pd(d, sq, acc[2]);
    acc[3] = _mm256_fmadd_pd(d, cross, acc[3]);
}

/// The AVX2 build of [`super::block_portable`].
#[target_feature(enable = "avx2,fma")]
pub(super) fn block(v: &[DVec3], origin: DVec3, block: &[[u32; 3]]) -> Sums {
    let flat: &[f64] = bytemuck::cast_slice(v);
    let o = _mm256_set_pd(0.0, origin.z, origin.y, origin.x);
    let mut even = [_mm256_setzero_pd(); 4];
    let mut odd = even;
    let mut pairs = block.chunks_exact(2);
    for pair in pairs.by_ref() {
        // SAFETY: the indices come from a TriMesh, so they are in range.
        unsafe {
            add_triangle(&mut even, flat, o, pair[0]);
            add_triangle(&mut odd, flat, o, pair[1]);
        }
    }
    if let Some(&t) = pairs.remainder().first() {
        // SAFETY: as above.
        unsafe { add_triangle(&mut even, flat, o, t) };
    }
    super::Lanes {
        volume: lanes(_mm256_add_pd(even[0], odd[0]))[0],
        first: lanes(_mm256_add_pd(even[1], odd[1])),
        diagonal: lanes(_mm256_add_pd(even[2], odd[2])),
        off: lanes(_mm256_add_pd(even[3], odd[3])),
    }
    .sums()
}
