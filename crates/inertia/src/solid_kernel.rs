//! The hot loop of [`crate::MeshMoments::solid`]: four triangles per step in
//! lanes that the compiler turns into SIMD, with fused multiply-adds where
//! the CPU has them.
//!
//! This is the one module with `unsafe`: calling the AVX2/FMA build of the
//! kernel after checking at run time that the CPU supports it. Measured
//! (BENCHMARKS.md): 13.3 ns per triangle for the plain scalar loop, ≈3 ns
//! with AVX2 + FMA lanes.

use glam::DVec3;

/// Triangles per step.
const LANES: usize = 4;
/// Triangles summed into one partial sum before it is added to the total,
/// so rounding errors grow like `n/B + B` instead of `n`.
const BLOCK: usize = 512;

/// Ten running sums: Σd, Σd·s (x, y, z), Σd·(sᵢsⱼ + Σₖ aₖᵢaₖⱼ) for xx, yy,
/// zz, xy, xz, yz — with `d = a·(b×c)`, `s = a + b + c` per triangle.
pub(crate) type Sums = [f64; 10];

type Lanes = [f64; LANES];

// Lane-wise arithmetic as plain `#[inline(always)]` functions: closures
// would not be inlined into the AVX2 build (they do not inherit its target
// features), and each call would cost more than the arithmetic.

#[inline(always)]
fn add(a: Lanes, b: Lanes) -> Lanes {
    core::array::from_fn(|l| a[l] + b[l])
}

#[inline(always)]
fn sub(a: Lanes, b: Lanes) -> Lanes {
    core::array::from_fn(|l| a[l] - b[l])
}

#[inline(always)]
fn mul(a: Lanes, b: Lanes) -> Lanes {
    core::array::from_fn(|l| a[l] * b[l])
}

/// `a·b + c` lane by lane, fused (one rounding) when `FMA`.
#[inline(always)]
fn madd<const FMA: bool>(a: Lanes, b: Lanes, c: Lanes) -> Lanes {
    core::array::from_fn(|l| {
        if FMA {
            a[l].mul_add(b[l], c[l])
        } else {
            a[l] * b[l] + c[l]
        }
    })
}

/// Corner `k` of four triangles, relative to `origin`, as x, y, z lanes.
#[inline(always)]
fn corner(v: &[DVec3], origin: DVec3, quad: &[[u32; 3]; LANES], k: usize) -> [Lanes; 3] {
    let mut out = [[0.0; LANES]; 3];
    for l in 0..LANES {
        let p = v[quad[l][k] as usize] - origin;
        out[0][l] = p.x;
        out[1][l] = p.y;
        out[2][l] = p.z;
    }
    out
}

/// `sᵢsⱼ + aᵢaⱼ + bᵢbⱼ + cᵢcⱼ`, lane by lane.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn second<const FMA: bool>(
    si: Lanes,
    sj: Lanes,
    ai: Lanes,
    aj: Lanes,
    bi: Lanes,
    bj: Lanes,
    ci: Lanes,
    cj: Lanes,
) -> Lanes {
    madd::<FMA>(
        si,
        sj,
        madd::<FMA>(ai, aj, madd::<FMA>(bi, bj, mul(ci, cj))),
    )
}

/// One step: four triangles' contributions added to `acc`.
#[inline(always)]
fn step<const FMA: bool>(
    acc: &mut [Lanes; 10],
    v: &[DVec3],
    origin: DVec3,
    quad: &[[u32; 3]; LANES],
) {
    let [ax, ay, az] = corner(v, origin, quad, 0);
    let [bx, by, bz] = corner(v, origin, quad, 1);
    let [cx, cy, cz] = corner(v, origin, quad, 2);
    // d = a · (b × c): six times the signed volume of (origin, a, b, c).
    let nx = sub(mul(by, cz), mul(bz, cy));
    let ny = sub(mul(bz, cx), mul(bx, cz));
    let nz = sub(mul(bx, cy), mul(by, cx));
    let d = madd::<FMA>(ax, nx, madd::<FMA>(ay, ny, mul(az, nz)));
    let (sx, sy, sz) = (
        add(add(ax, bx), cx),
        add(add(ay, by), cy),
        add(add(az, bz), cz),
    );
    let q = second::<FMA>;
    let terms = [
        sx,
        sy,
        sz,
        q(sx, sx, ax, ax, bx, bx, cx, cx),
        q(sy, sy, ay, ay, by, by, cy, cy),
        q(sz, sz, az, az, bz, bz, cz, cz),
        q(sx, sy, ax, ay, bx, by, cx, cy),
        q(sx, sz, ax, az, bx, bz, cx, cz),
        q(sy, sz, ay, az, by, bz, cy, cz),
    ];
    acc[0] = add(acc[0], d);
    for (a, t) in acc[1..].iter_mut().zip(terms) {
        *a = madd::<FMA>(d, t, *a);
    }
}

/// The sums over all triangles, blockwise, four lanes at a time.
#[inline(always)]
fn sums<const FMA: bool>(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]]) -> Sums {
    let mut total = [0.0; 10];
    for block in triangles.chunks(BLOCK) {
        let mut acc = [[0.0; LANES]; 10];
        let mut quads = block.chunks_exact(LANES);
        for quad in &mut quads {
            // chunks_exact yields slices of exactly LANES triangles.
            let quad: &[[u32; 3]; LANES] = quad.try_into().unwrap_or(&[[0; 3]; LANES]);
            step::<FMA>(&mut acc, v, origin, quad);
        }
        // Pad the rest with [0, 0, 0]: a = b = c gives d = 0 and adds nothing.
        let rest = quads.remainder();
        if !rest.is_empty() {
            let mut pad = [[0u32; 3]; LANES];
            pad[..rest.len()].copy_from_slice(rest);
            step::<FMA>(&mut acc, v, origin, &pad);
        }
        for (t, lanes) in total.iter_mut().zip(acc) {
            *t += lanes.iter().sum::<f64>();
        }
    }
    total
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn sums_avx2_fma(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]]) -> Sums {
    sums::<true>(v, origin, triangles)
}

/// The ten sums of a mesh's triangles about `origin` (every index must be
/// in range for `v`; [`crate::TriMesh`] guarantees it).
#[allow(unsafe_code)]
pub(crate) fn solid_sums(v: &[DVec3], origin: DVec3, triangles: &[[u32; 3]]) -> Sums {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: `sums_avx2_fma` only needs AVX2 and FMA, which the CPU
        // has (checked just above); it is otherwise safe code.
        return unsafe { sums_avx2_fma(v, origin, triangles) };
    }
    sums::<false>(v, origin, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plain and the fused kernels agree, and both match a direct sum.
    #[test]
    fn lanes_padding_and_fma_agree_with_direct_sum() {
        let v: Vec<DVec3> = (0..40)
            .map(|i| {
                let t = i as f64;
                DVec3::new(t.sin(), (1.3 * t).cos(), (0.7 * t).sin() * 2.0)
            })
            .collect();
        // 37 triangles: 9 full steps and a padded one.
        let tris: Vec<[u32; 3]> = (0..37u32)
            .map(|i| [i, (i + 1) % 40, (i * 7 + 3) % 40])
            .collect();
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
            let terms = [
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
            for (acc, t) in direct.iter_mut().zip(terms) {
                *acc += d * t;
            }
        }
        for fast in [
            sums::<false>(&v, origin, &tris),
            solid_sums(&v, origin, &tris),
        ] {
            for (x, y) in fast.iter().zip(&direct) {
                assert!((x - y).abs() < 1e-13 * y.abs().max(1.0), "{x} vs {y}");
            }
        }
    }
}
