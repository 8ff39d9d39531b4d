//! AVX-512: the AVX2 loop with two triangles per 512-bit register, the
//! even one in the low half, the odd one in the high half (the in-lane
//! permutations work on both halves).

#![allow(unsafe_code)]

use core::arch::x86_64::*;

use super::Sums;
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

/// Lanes 0, 1, 2 of the low half plus the high half (even + odd).
#[inline]
#[target_feature(enable = "avx512f,avx512vl,fma")]
fn lanes(a: __m512d) -> [f64; 3] {
    let h = _mm256_add_pd(_mm512_castpd512_pd256(a), _mm512_extractf64x4_pd::<1>(a));
    let mut out = [0.0; 4];
    // SAFETY: `out` holds four f64 (an unaligned store).
    unsafe { _mm256_storeu_pd(out.as_mut_ptr(), h) };
    [out[0], out[1], out[2]]
}

/// Adds triangles `t0` (low half) and `t1` (high half) to the
/// accumulators (volume, first, diagonal, off-diagonal), only the
/// halves whose lanes are set in `keep` (`0xff` both, `0x0f` the low).
///
/// # Safety
/// The indices are in range for `flat` (see [`corners`]).
#[inline]
#[target_feature(enable = "avx512f,avx512vl,fma")]
unsafe fn add_pair(
    acc: &mut [__m512d; 4],
    flat: &[f64],
    o: __m512d,
    [t0, t1]: [[u32; 3]; 2],
    keep: __mmask8,
) {
    // SAFETY: the caller's promise.
    let (a, b, c) = unsafe {
        (
            corners(flat, o, t0[0], t1[0]),
            corners(flat, o, t0[1], t1[1]),
            corners(flat, o, t0[2], t1[2]),
        )
    };
    let (a1, b1, c1) = (yzx(a), yzx(b), yzx(c));
    let m = _mm512_fmsub_pd(b, c1, _mm512_mul_pd(b1, c));
    let e = _mm512_mul_pd(zxy(a), m);
    let d = _mm512_add_pd(_mm512_add_pd(e, yzx(e)), zxy(e));
    let s = _mm512_add_pd(_mm512_add_pd(a, b), c);
    let sq = _mm512_fmadd_pd(
        s,
        s,
        _mm512_fmadd_pd(a, a, _mm512_fmadd_pd(b, b, _mm512_mul_pd(c, c))),
    );
    let cross = _mm512_fmadd_pd(
        s,
        yzx(s),
        _mm512_fmadd_pd(a, a1, _mm512_fmadd_pd(b, b1, _mm512_mul_pd(c, c1))),
    );
    acc[0] = _mm512_mask_add_pd(acc[0], keep, acc[0], d);
    acc[1] = _mm512_mask3_fmadd_pd(d, s, acc[1], keep);
    acc[2] = _mm512_mask3_fmadd_pd(d, sq, acc[2], keep);
    acc[3] = _mm512_mask3_fmadd_pd(d, cross, acc[3], keep);
}

/// The AVX-512 build of [`super::block_portable`].
#[target_feature(enable = "avx512f,avx512vl,fma")]
pub(super) fn block(v: &[DVec3], origin: DVec3, block: &[[u32; 3]]) -> Sums {
    let flat: &[f64] = bytemuck::cast_slice(v);
    let o = _mm512_set_pd(
        0.0, origin.z, origin.y, origin.x, 0.0, origin.z, origin.y, origin.x,
    );
    let mut acc = [_mm512_setzero_pd(); 4];
    let mut pairs = block.chunks_exact(2);
    for pair in pairs.by_ref() {
        // SAFETY: the indices come from a TriMesh, so they are in range.
        unsafe { add_pair(&mut acc, flat, o, [pair[0], pair[1]], 0xff) };
    }
    if let Some(&t) = pairs.remainder().first() {
        // An odd last triangle: the high half loads it again but keeps
        // its accumulators unchanged.
        // SAFETY: as above.
        unsafe { add_pair(&mut acc, flat, o, [t, t], 0x0f) };
    }
    super::Lanes {
        volume: lanes(acc[0])[0],
        first: lanes(acc[1]),
        diagonal: lanes(acc[2]),
        off: lanes(acc[3]),
    }
    .sums()
}
