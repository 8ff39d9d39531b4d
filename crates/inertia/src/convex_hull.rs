//! The convex hull of a point set as a closed, outward-wound mesh, checked
//! before it is returned.
//!
//! parry's quickhull (0.31) scales the points by their bounding-box diagonal
//! and then decides visibility with absolute epsilons, so a thin point set
//! is nearly flat to it: on a 1 m × 1 mm ellipsoid of 500 points it keeps 54
//! hull vertices and encloses 3.4 % of the true volume; on a 1 m × 1 mm × 1 m
//! one of 2000 points it returns an inside-out hull (volume −1.7 %), and it
//! reports neither. The hull of an affine image is the affine image of the
//! hull, so kreisel builds the hull of the points in their *whitened* frame (the
//! principal axes of the point cloud, each scaled to unit half-extent),
//! where every set is round, and maps the hull's vertices back to the input
//! points exactly (by identity, not by the inverse map). Measured on the sets
//! above: all 500 (2000) points on the hull, volume within the polyhedral
//! discretisation error of the ellipsoid (tests below and
//! `tests/hull_reference.rs`).
//!
//! Before the hull is built, exact duplicates are dropped and an
//! Akl–Toussaint prefilter discards every point strictly inside the hull of
//! the extreme points in 256 directions (a point inside a polytope spanned
//! by input points is no hull vertex). The hull itself is kreisel's own
//! conflict-list quickhull ([`crate::quickhull`]), chosen by measurement:
//! parry 0.31's quickhull grows badly with the hull's size, scipy's Qhull
//! takes 25 s on the UV sphere below, `chull` 0.2.4 (f64, "fast" mode)
//! over 120 s on a tenth of it and 17 s on a tenth of the bumpy one, and
//! `quickhull` 0.1 is f32 only (no exact vertex identity). Measured
//! (release, `/usr/bin/time kreisel inertia FILE --hull --format json`, 2
//! shared cores, user time; `tests/data/gen/hull_sphere.py` makes the files):
//!
//! ```text
//! input (2.56 M triangles, 1.28 M points)  hull vertices  now       parry
//! UV sphere, every point on the hull       1 277 351      5.1–7 s   165 s (305 s wall)
//! bumpy sphere                               138 759      1.8–2.4 s 7.2 s
//! ```
//!
//! with volumes within 3e-14 of scipy's Qhull on the same points (UV
//! sphere: 1051 points near the poles lie within 2e-10 of the half-extent
//! of the hull's faces and are left out; Qhull keeps all). UV sphere phases:
//! prefilter 0.6 s (keeps every point), quickhull 2.5 s, check 2 s. When
//! both quickhull policies fail the check (CAD meshes full of coplanar and
//! cocircular points), parry's quickhull is tried last, checked the same
//! way. On the 1178 STL/OBJ meshes of pybullet_data that trimesh and scipy
//! read, `--hull --merge --weld off` agrees with Qhull to 7e-12 on all.
//!
//! Nothing is trusted: the result must be a closed surface in which every
//! edge is used once in each direction (V − E + F = 2), with positive
//! volume, every face facing away from the vertices' centroid, covering
//! the directions from it once (solid angles summing to 4π), convex at
//! every edge, and containing every input point within `1e-9` of the point
//! set's extent along each principal axis. A hull that fails is an
//! [`InertiaError::HullCheckFailed`], never a silent number. Containment is
//! tested by a walk over the hull's faces that maximises the linear
//! function `n·(p − c) / n·(v − c)` on the polar dual (the simplex method's
//! argument: on a convex polytope a local maximum is the global one; the
//! walk also searches [`PLATEAU`] below its best, past the tiny dents the
//! tolerances allow); the points are taken in the order of their
//! direction's cell on a cube map, each walk starting where the last one
//! ended, so a walk is a few steps instead of F tests. The points the
//! prefilter drops are inside a polytope (itself checked the same way)
//! whose corners are checked points, so inside the hull as well.

use glam::{DMat3, DVec3};

use crate::quickhull::{Visibility, quickhull};
use crate::{InertiaError, PrincipalAxes, TriMesh};

/// A point set thinner than this, relative to its largest extent, spans no
/// volume (rounding in the principal frame is ~1e-16 of the extent).
const FLAT_RELATIVE: f64 = 1e-10;

/// How far outside the hull a point may lie, in whitened units (each
/// principal extent is 2).
const CONTAIN_TOLERANCE: f64 = 1e-9;

/// The prefilter keeps points within this whitened distance of its
/// polytope's faces, so that rounding cannot discard a hull vertex.
const PREFILTER_MARGIN: f64 = 1e-9;

/// The convex hull of a mesh's vertices, as an outward-wound closed mesh.
///
/// The hull's vertices are input vertices (bit for bit). See the module
/// documentation for how it is built and checked.
///
/// # Errors
/// [`InertiaError::DegenerateHull`] for fewer than four distinct points, or
/// points that all lie on one line or in one plane (within `1e-10` of their
/// size); [`InertiaError::HullCheckFailed`] if quickhull gives up or its
/// hull fails the checks (not closed, not outward, not convex, or missing a point).
///
/// ```
/// use glam::DVec3;
/// use kreisel_inertia::{convex_hull, MeshMoments, TriMesh};
/// // A tetrahedron's corners plus an inner point: the hull drops the inner point.
/// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z, DVec3::splat(0.1)];
/// let mesh = TriMesh::new(v, vec![[0, 1, 4]]);
/// let hull = convex_hull(&mesh)?;
/// assert_eq!(hull.triangles().len(), 4);
/// assert!((MeshMoments::solid(&hull).zeroth - 1.0 / 6.0).abs() < 1e-15);
/// // A 1 m x 1 mm x 1 mm box: thin, but a solid.
/// let thin: Vec<DVec3> = (0..8)
///     .map(|i| DVec3::new((i & 1) as f64, 1e-3 * ((i >> 1) & 1) as f64, 1e-3 * (i >> 2) as f64))
///     .collect();
/// let hull = convex_hull(&TriMesh::new(thin, vec![[0, 1, 2]]))?;
/// assert!((MeshMoments::solid(&hull).zeroth - 1e-6).abs() < 1e-20);
/// # Ok::<(), kreisel_inertia::InertiaError>(())
/// ```
pub fn convex_hull(mesh: &TriMesh) -> Result<TriMesh, InertiaError> {
    let points = distinct(mesh.vertices());
    let frame = Whitening::of(&points)?;
    let white: Vec<DVec3> = points.iter().map(|&p| frame.apply(p)).collect();
    let candidates = prefilter(&white);
    let fail = |reason: String| InertiaError::HullCheckFailed {
        points: points.len(),
        reason,
    };
    // Coplanar faces: replace them, or if that fails the check keep them
    // (see `quickhull.rs`); the first hull that passes is returned.
    let mut failures = Vec::new();
    for (visibility, how) in [
        (Visibility::Inclusive, "replacing coplanar faces"),
        (Visibility::Strict, "keeping coplanar faces"),
    ] {
        let checked = quickhull(&white, &candidates, visibility)
            .map_err(|e| format!("quickhull: {e}"))
            .and_then(|(hull_index, triangles)| {
                let white_hull: Vec<DVec3> = hull_index.iter().map(|&i| white[i]).collect();
                check_hull(&white_hull, &triangles, &candidates, &white)?;
                Ok((hull_index, triangles))
            });
        match checked {
            Ok((hull_index, triangles)) => {
                let vertices = hull_index.iter().map(|&i| points[i]).collect();
                return TriMesh::try_new(vertices, triangles);
            }
            Err(reason) => failures.push(format!("{how}: {reason}")),
        }
    }
    // Last, parry's quickhull (slow on big hulls, but it handles some CAD
    // meshes, full of coplanar and cocircular points, that both of the
    // above fail on: 2 of 1188 pybullet meshes). Without the `parry`
    // feature those meshes are `HullCheckFailed`.
    #[cfg(feature = "parry")]
    match parry_hull(&white, &candidates) {
        Ok((hull_index, triangles)) => {
            let white_hull: Vec<DVec3> = hull_index.iter().map(|&i| white[i]).collect();
            match check_hull(&white_hull, &triangles, &candidates, &white) {
                Ok(()) => {
                    let vertices = hull_index.iter().map(|&i| points[i]).collect();
                    return TriMesh::try_new(vertices, triangles);
                }
                Err(reason) => failures.push(format!("parry: {reason}")),
            }
        }
        Err(reason) => failures.push(format!("parry: {reason}")),
    }
    Err(fail(failures.join("; ")))
}

/// parry's hull of `white[candidates]`, its vertices mapped back to input
/// indices by their bits.
#[cfg(feature = "parry")]
fn parry_hull(
    white: &[DVec3],
    candidates: &[usize],
) -> Result<(Vec<usize>, Vec<[u32; 3]>), String> {
    let parry_points: Vec<_> = candidates
        .iter()
        .map(|&i| crate::to_parry(white[i]))
        .collect();
    let (hull_points, triangles) = parry3d_f64::transformation::try_convex_hull(&parry_points)
        .map_err(|e| format!("quickhull failed: {e:?}"))?;
    let index_of: std::collections::HashMap<[u64; 3], usize> =
        candidates.iter().map(|&i| (bits(white[i]), i)).collect();
    let hull_index = hull_points
        .iter()
        .map(|p| {
            index_of
                .get(&bits(crate::from_parry(*p)))
                .copied()
                .ok_or_else(|| "it returned a vertex that is no input point".to_string())
        })
        .collect::<Result<_, _>>()?;
    Ok((hull_index, triangles))
}

/// The distinct points (exact duplicates, and −0 against 0, removed).
fn distinct(vertices: &[DVec3]) -> Vec<DVec3> {
    let mut keyed: Vec<([u64; 3], DVec3)> = vertices
        .iter()
        .map(|&v| (bits(v + DVec3::ZERO), v + DVec3::ZERO))
        .collect();
    keyed.sort_unstable_by_key(|a| a.0);
    keyed.dedup_by(|a, b| a.0 == b.0);
    keyed.into_iter().map(|(_, v)| v).collect()
}

/// `x ≤ bound`, or NaN.
fn not_above(x: f64, bound: f64) -> bool {
    x.partial_cmp(&bound) != Some(core::cmp::Ordering::Greater)
}

/// The bit patterns of a point's coordinates.
fn bits(v: DVec3) -> [u64; 3] {
    v.to_array().map(f64::to_bits)
}

/// The affine map to the whitened frame: principal axes of the point cloud,
/// each coordinate scaled to `[-1, 1]`.
struct Whitening {
    /// Centre of the box in the principal frame, in input coordinates.
    center: DVec3,
    /// `diag(1/half-extent) · Rᵀ`.
    linear: DMat3,
}

impl Whitening {
    /// The whitening of a point set, or why it spans no volume.
    fn of(points: &[DVec3]) -> Result<Self, InertiaError> {
        if points.len() < 4 {
            return Err(InertiaError::DegenerateHull {
                reason: format!(
                    "{} distinct points (a solid needs at least 4)",
                    points.len()
                ),
            });
        }
        let n = points.len() as f64;
        let mean = points.iter().fold(DVec3::ZERO, |s, &p| s + p / n);
        let mut cov = DMat3::ZERO;
        for &p in points {
            let d = p - mean;
            cov += DMat3::from_cols(d * d.x, d * d.y, d * d.z);
        }
        let axes = PrincipalAxes::from_tensor(cov).axes;
        let rt = axes.transpose();
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &p in points {
            let q = rt * (p - mean);
            lo = lo.min(q);
            hi = hi.max(q);
        }
        let half = (hi - lo) / 2.0;
        let largest = half.max_element();
        // NaN is degenerate too.
        if not_above(half.min_element(), FLAT_RELATIVE * largest) {
            let what = if half
                .x
                .max(half.y)
                .min(half.y.max(half.z))
                .min(half.x.max(half.z))
                > FLAT_RELATIVE * largest
            {
                "in one plane"
            } else {
                "on one line"
            };
            return Err(InertiaError::DegenerateHull {
                reason: format!(
                    "the {} points lie {what} (thickness {:e} for a size of {:e}): they span no volume",
                    points.len(),
                    2.0 * half.min_element(),
                    2.0 * largest
                ),
            });
        }
        Ok(Self {
            center: mean + axes * ((lo + hi) / 2.0),
            linear: DMat3::from_diagonal(half.recip()) * rt,
        })
    }

    /// A point in the whitened frame.
    fn apply(&self, p: DVec3) -> DVec3 {
        self.linear * (p - self.center)
    }
}

/// Akl–Toussaint: the indices of the points that may be hull vertices (all
/// but those strictly inside the hull of the extremes in [`DIRECTIONS`]
/// directions, which the face walk of [`climb`] tests in about √F steps).
fn prefilter(white: &[DVec3]) -> Vec<usize> {
    let all = || (0..white.len()).collect::<Vec<_>>();
    if white.len() < 4 * DIRECTIONS {
        return all();
    }
    let directions = directions();
    let mut best = vec![(0usize, f64::NEG_INFINITY); directions.len()];
    for (i, p) in white.iter().enumerate() {
        for (b, d) in best.iter_mut().zip(&directions) {
            let v = d.dot(*p);
            if v > b.1 {
                *b = (i, v);
            }
        }
    }
    let mut extremes: Vec<usize> = best.iter().map(|b| b.0).collect();
    extremes.sort_unstable();
    extremes.dedup();
    // The filter polytope must pass the full check (a folded or dented one
    // would drop hull vertices).
    let Some((hp, tris)) = [Visibility::Inclusive, Visibility::Strict]
        .into_iter()
        .filter_map(|v| quickhull(white, &extremes, v).ok())
        .map(|(index, tris)| {
            (
                index.into_iter().map(|i| white[i]).collect::<Vec<_>>(),
                tris,
            )
        })
        .find(|(hp, tris)| check_hull(hp, tris, &extremes, white).is_ok())
    else {
        return all();
    };
    let Ok(neighbours) = face_graph(&tris) else {
        return all();
    };
    let planes = planes(&hp, &tris, DVec3::ZERO);
    // The filter polytope must be a convex solid around the origin (so the
    // walk finds the farthest face) to mean anything.
    let nearest = planes.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    if not_above(nearest, PREFILTER_MARGIN)
        || locally_convex(&hp, &tris, &neighbours, &planes, DVec3::ZERO).is_err()
    {
        return all();
    }
    let map = CubeMap::for_faces(tris.len());
    let mut starts = vec![0; map.len()];
    (0..white.len())
        .filter(|&i| {
            let p = white[i];
            let ratio = |k: usize| {
                let (n, off) = planes[k];
                n.dot(p) / off
            };
            let start = &mut starts[map.cell(p)];
            *start = climb(*start, &neighbours, &ratio);
            // Every plane at least `nearest · (1 − max ratio)` away.
            nearest * (1.0 - ratio(*start)) <= PREFILTER_MARGIN
        })
        .collect()
}

/// Directions binned on a cube map of `side × side` cells per cube face, so
/// that each face walk starts where the last walk in that direction ended.
struct CubeMap {
    /// Cells along each edge of a cube face.
    side: usize,
}

impl CubeMap {
    /// A map with about 48 of a hull's `faces` per cell (at least 16 × 16
    /// cells per cube face), so that a walk from the cell's last face is short.
    fn for_faces(faces: usize) -> Self {
        let side = ((faces / 48) as f64).sqrt() as usize;
        Self {
            side: side.clamp(16, 1024),
        }
    }

    /// The number of cells.
    fn len(&self) -> usize {
        6 * self.side * self.side
    }

    /// The cell of the direction of `p` (the origin and NaN fall in cell 0).
    fn cell(&self, p: DVec3) -> usize {
        let a = p.abs();
        let (axis, u, v, w) = if a.x >= a.y && a.x >= a.z {
            (0, p.y, p.z, p.x)
        } else if a.y >= a.z {
            (1, p.z, p.x, p.y)
        } else {
            (2, p.x, p.y, p.z)
        };
        let side = usize::from(w < 0.0);
        let m = w.abs();
        let half = self.side as f64 / 2.0;
        // NaN and 0/0 give 0.
        let bin = |t: f64| (((t / m + 1.0) * half) as usize).min(self.side - 1);
        ((2 * axis + side) * self.side + bin(u)) * self.side + bin(v)
    }
}

/// Every edge convex: the far corner of each neighbouring triangle is on
/// the inner side of the triangle's plane (within the containment
/// tolerance). `Err` names the first triangle where it is not, and by how much.
fn locally_convex(
    points: &[DVec3],
    triangles: &[[u32; 3]],
    neighbours: &[[usize; 3]],
    planes: &[(DVec3, f64)],
    c: DVec3,
) -> Result<(), (usize, f64)> {
    for (k, t) in triangles.iter().enumerate() {
        let (n, off) = planes[k];
        for (e, &g) in neighbours[k].iter().enumerate() {
            let far = triangles[g]
                .iter()
                .find(|&&i| i != t[e] && i != t[(e + 1) % 3])
                .map_or(c, |&i| points[i as usize]);
            let excess = n.dot(far - c) - off;
            if excess.is_nan() || excess > CONTAIN_TOLERANCE {
                return Err((k, excess));
            }
        }
    }
    Ok(())
}

/// How many directions the prefilter takes extremes in.
const DIRECTIONS: usize = 256;

/// [`DIRECTIONS`] directions spread evenly over the sphere.
fn directions() -> Vec<DVec3> {
    fibonacci_sphere(DIRECTIONS)
}

/// `n` unit vectors spread evenly over the sphere (a Fibonacci lattice).
fn fibonacci_sphere(n: usize) -> Vec<DVec3> {
    let golden = core::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - z * z).sqrt();
            let t = golden * i as f64;
            DVec3::new(r * t.cos(), r * t.sin(), z)
        })
        .collect()
}

/// The face across each edge of each triangle of a closed surface in which
/// every edge is used once in each direction, or where that fails.
///
/// The edges are sorted by their undirected key (a sort, not a hash map: 3
/// times faster on the 7.7 M edge uses of a 2.56 M-triangle hull).
fn face_graph(triangles: &[[u32; 3]]) -> Result<Vec<[usize; 3]>, String> {
    // (undirected key, use index 3k + e, runs from the smaller end).
    let mut uses: Vec<(u64, u32, bool)> = Vec::with_capacity(3 * triangles.len());
    for (k, t) in triangles.iter().enumerate() {
        for e in 0..3 {
            let (a, b) = (t[e], t[(e + 1) % 3]);
            if a == b {
                return Err(format!("triangle {k} repeats vertex {a}"));
            }
            let key = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
            let at = u32::try_from(3 * k + e).map_err(|_| "over 2³² edge uses")?;
            uses.push((key, at, a < b));
        }
    }
    uses.sort_unstable_by_key(|u| u.0);
    let mut neighbours = vec![[0; 3]; triangles.len()];
    let mut rest = uses.as_slice();
    while let [first, tail @ ..] = rest {
        let (a, b) = ((first.0 >> 32) as u32, first.0 as u32);
        let [second, tail @ ..] = tail else {
            return Err(format!("the surface is open at edge {a}-{b}"));
        };
        if second.0 != first.0 {
            return Err(format!("the surface is open at edge {a}-{b}"));
        }
        if second.2 == first.2 || tail.first().is_some_and(|u| u.0 == first.0) {
            return Err(format!(
                "edge {a}-{b} is used more than once in one direction"
            ));
        }
        let (x, y) = (first.1 as usize, second.1 as usize);
        neighbours[x / 3][x % 3] = y / 3;
        neighbours[y / 3][y % 3] = x / 3;
        rest = tail;
    }
    Ok(neighbours)
}

/// Each triangle's unit normal and its distance from `c` (zero normal for a
/// triangle without area).
fn planes(points: &[DVec3], triangles: &[[u32; 3]], c: DVec3) -> Vec<(DVec3, f64)> {
    triangles
        .iter()
        .map(|t| {
            let [a, b, d] = t.map(|i| points[i as usize] - c);
            let n = (b - a).cross(d - a);
            let len = n.length();
            let n = if len > 0.0 { n / len } else { DVec3::ZERO };
            (n, n.dot(a))
        })
        .collect()
}

/// Checks a hull in whitened coordinates: closed and consistently wound,
/// of sphere topology, outward, convex at every edge, and containing every
/// candidate point. The points the prefilter dropped lie inside its
/// (checked convex) polytope of candidates, so inside the hull too.
fn check_hull(
    hull: &[DVec3],
    triangles: &[[u32; 3]],
    candidates: &[usize],
    white: &[DVec3],
) -> Result<(), String> {
    let f = triangles.len();
    if f < 4 {
        return Err(format!("{f} triangles cannot close a solid"));
    }
    // Every directed edge once, its reverse once.
    let neighbours = face_graph(triangles)?;
    let used = {
        let mut used = vec![false; hull.len()];
        triangles
            .iter()
            .flatten()
            .for_each(|&i| used[i as usize] = true);
        used.iter().filter(|&&u| u).count()
    };
    // Euler: V − E + F = 2 with E = 3F/2, i.e. 2V = F + 4.
    if 2 * used != f + 4 {
        return Err(format!(
            "the surface is no sphere: {used} vertices, {f} triangles (V − E + F ≠ 2)"
        ));
    }
    let c = hull.iter().fold(DVec3::ZERO, |s, &p| s + p) / hull.len() as f64;
    let volume: f64 = triangles
        .iter()
        .map(|t| {
            let [a, b, d] = t.map(|i| hull[i as usize] - c);
            a.dot(b.cross(d)) / 6.0
        })
        .sum();
    let planes = planes(hull, triangles, c);
    if not_above(volume, 0.0) {
        return Err(format!("the surface is inside out (volume {volume:e})"));
    }
    // The vertices' centroid is inside a convex hull, below every face: a
    // face facing it is folded back (or has no area), which the edge test
    // cannot see when the fold lies in one plane.
    if let Some(k) = planes.iter().position(|p| not_above(p.1, 0.0)) {
        return Err(format!("triangle {k} faces inward (or has no area)"));
    }
    // Seen from the centroid, the faces must cover the sphere of directions
    // once (solid angles summing to 4π), not wind around it twice: with the
    // edge test below, the surface is then convex, and the walks find the
    // farthest face.
    let turns: f64 = triangles
        .iter()
        .map(|t| {
            let [a, b, d] = t.map(|i| hull[i as usize] - c);
            let (la, lb, ld) = (a.length(), b.length(), d.length());
            let below = la * lb * ld + a.dot(b) * ld + a.dot(d) * lb + b.dot(d) * la;
            2.0 * a.dot(b.cross(d)).atan2(below)
        })
        .sum::<f64>()
        / (4.0 * core::f64::consts::PI);
    if turns.is_nan() || (turns - 1.0).abs() >= 1e-6 {
        return Err(format!(
            "the surface winds {turns} times around its centre (a convex one, once)"
        ));
    }
    if let Err((k, excess)) = locally_convex(hull, triangles, &neighbours, &planes, c) {
        return Err(format!(
            "the surface is not convex at triangle {k} (a neighbour rises {excess:e} of the half-extent above it)"
        ));
    }
    // Containment: a walk to the face of largest n·(p − c)/off.
    let reach = planes.iter().map(|p| p.1).fold(0.0_f64, f64::max);
    // Points in cube-map cell order, each walk starting where the last one
    // ended: near its point.
    let map = CubeMap::for_faces(f);
    let mut order: Vec<(usize, usize)> = candidates
        .iter()
        .map(|&i| (map.cell(white[i] - c), i))
        .collect();
    order.sort_unstable();
    let mut last = 0;
    for (_, i) in order {
        let p = white[i] - c;
        let ratio = |k: usize| {
            let (n, off) = planes[k];
            if off > 0.0 {
                n.dot(p) / off
            } else {
                f64::NEG_INFINITY
            }
        };
        let best = climb(last, &neighbours, &ratio);
        last = best;
        let excess = (ratio(best) - 1.0) * reach;
        if excess.is_nan() || excess > CONTAIN_TOLERANCE {
            return Err(format!(
                "input point {i} lies outside the hull ({excess:e} of the half-extent)"
            ));
        }
    }
    Ok(())
}

/// How far below the best value the walk of [`climb`] still searches for a
/// way up (relative): coplanar triangles share one dual vertex, and the
/// dents the checks allow (up to [`CONTAIN_TOLERANCE`]) between nearly
/// coplanar ones make false local maxima. Regression: with 1e-12 the walk
/// stopped at 0.985 of the true maximum on a pybullet mesh (xarm6
/// `base.stl`), and the prefilter dropped 51 hull points.
const PLATEAU: f64 = 1e-8;

/// The face maximising `value` on the face graph, from `start`: greedy
/// ascent, widened over plateaus (coplanar triangles share one dual vertex).
fn climb(start: usize, neighbours: &[[usize; 3]], value: &dyn Fn(usize) -> f64) -> usize {
    let mut at = start;
    let mut best = value(at);
    loop {
        let next = neighbours[at]
            .iter()
            .map(|&g| (g, value(g)))
            .fold((at, best), |a, b| if b.1 > a.1 { b } else { a });
        if next.0 != at {
            (at, best) = next;
            continue;
        }
        // A plateau: search the faces of (nearly) equal value for a way up.
        let level = best - PLATEAU * best.abs().max(1.0);
        let mut seen = vec![at];
        let mut queue = vec![at];
        let mut up = None;
        while let Some(k) = queue.pop() {
            for &g in &neighbours[k] {
                if seen.contains(&g) {
                    continue;
                }
                let v = value(g);
                if v > best {
                    up = Some((g, v));
                    break;
                }
                if v >= level && seen.len() < 4096 {
                    seen.push(g);
                    queue.push(g);
                }
            }
            if up.is_some() {
                break;
            }
        }
        match up {
            Some(next) => (at, best) = next,
            None => return at,
        }
    }
}

#[cfg(test)]
mod tests {
    use std::collections::HashMap;

    use super::*;
    use crate::MeshMoments;

    /// `n` points on an ellipsoid of semi-axes `s` (Fibonacci lattice).
    fn ellipsoid_points(n: usize, s: DVec3) -> Vec<DVec3> {
        super::fibonacci_sphere(n)
            .into_iter()
            .map(|p| p * s)
            .collect()
    }

    fn hull_of(points: Vec<DVec3>) -> Result<TriMesh, InertiaError> {
        convex_hull(&TriMesh::new(points, vec![[0, 1, 2]]))
    }

    #[test]
    fn flat_ellipsoid_keeps_every_point_and_its_volume() {
        // Regression: parry alone kept 54 of 500 points, 3.4 % of the volume.
        let round = ellipsoid_points(500, DVec3::splat(0.5));
        for s in [
            DVec3::new(0.5, 0.5, 0.0005),
            DVec3::new(0.5, 0.0005, 0.5),
            DVec3::new(0.0005, 0.5, 0.5),
        ] {
            let hull = hull_of(ellipsoid_points(500, s)).unwrap();
            assert_eq!(hull.vertices().len(), 500, "{s}");
            // The affine image of the round hull: volume scales by the determinant.
            let round_volume = MeshMoments::solid(&hull_of(round.clone()).unwrap()).zeroth;
            let expected = round_volume * (s.x * s.y * s.z) / 0.125;
            let volume = MeshMoments::solid(&hull).zeroth;
            assert!(
                (volume / expected - 1.0).abs() < 1e-12,
                "{s}: {volume} vs {expected}"
            );
        }
    }

    #[test]
    fn coplanar_and_collinear_sets_are_clear_errors() {
        let plane: Vec<DVec3> = (0..50)
            .map(|i| DVec3::new((i % 7) as f64, (i / 7) as f64, 0.0))
            .collect();
        let line: Vec<DVec3> = (0..50).map(|i| DVec3::splat(i as f64)).collect();
        for (points, what) in [(plane, "in one plane"), (line, "on one line")] {
            let e = hull_of(points).unwrap_err().to_string();
            assert!(e.contains(what), "{e}");
        }
        let e = hull_of(vec![DVec3::ZERO, DVec3::X, DVec3::X, DVec3::Y]).unwrap_err();
        assert!(e.to_string().contains("3 distinct points"), "{e}");
    }

    #[test]
    fn prefilter_keeps_the_hull_of_a_big_set() {
        // A ball of random points with a few far corners: the prefilter drops
        // most points, the hull must still contain them all (checked inside).
        let mut s: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut r = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let points: Vec<DVec3> = (0..20_000)
            .map(|_| DVec3::new(r(), r(), 0.01 * r()))
            .collect();
        let white: Vec<DVec3> = {
            match convex_hull(&TriMesh::new(points.clone(), vec![[0, 1, 2]])) {
                Ok(h) => {
                    let mut worst: f64 = 0.0;
                    for t in h.triangles() {
                        let [a, b, cc] = h.corners(*t);
                        let n = (b - a).cross(cc - a).normalize();
                        for p in &points {
                            worst = worst.max(n.dot(*p - a));
                        }
                    }
                    eprintln!(
                        "convex_hull: {} verts vol {:e} worst {worst:e}",
                        h.vertices().len(),
                        crate::MeshMoments::solid(&h).zeroth
                    );
                }
                Err(e) => eprintln!("convex_hull: {e}"),
            }
            let points = distinct(&points);
            let w = Whitening::of(&points).unwrap();
            points.iter().map(|&p| w.apply(p)).collect()
        };
        let kept = prefilter(&white);
        assert!(kept.len() < points.len() / 2, "{}", kept.len());
        let hull = hull_of(points.clone()).unwrap();
        // Brute-force containment against every face, in input coordinates.
        for t in hull.triangles() {
            let [a, b, c] = hull.corners(*t);
            let n = (b - a).cross(c - a).normalize();
            for p in &points {
                assert!(n.dot(*p - a) < 1e-12, "{p}");
            }
        }
    }

    #[test]
    fn the_walk_finds_the_farthest_face() {
        // On a convex hull the walk's maximum equals the brute-force maximum.
        let points = ellipsoid_points(300, DVec3::new(1.0, 0.3, 0.01));
        let w = Whitening::of(&points).unwrap();
        let white: Vec<DVec3> = points.iter().map(|&p| w.apply(p)).collect();
        let all: Vec<usize> = (0..white.len()).collect();
        let (hp, tris) = quickhull(&white, &all, Visibility::Inclusive).unwrap();
        let hull: Vec<DVec3> = hp.into_iter().map(|i| white[i]).collect();
        let mut edge_face = HashMap::new();
        for (k, t) in tris.iter().enumerate() {
            for e in 0..3 {
                edge_face.insert((t[e], t[(e + 1) % 3]), k);
            }
        }
        let neighbours: Vec<[usize; 3]> = tris
            .iter()
            .map(|t| core::array::from_fn(|e| edge_face[&(t[(e + 1) % 3], t[e])]))
            .collect();
        let value_of = |p: DVec3, t: &[u32; 3]| {
            let [a, b, c] = t.map(|i| hull[i as usize]);
            let n = (b - a).cross(c - a);
            n.dot(p) / n.dot(a)
        };
        for k in 0..200 {
            let p = DVec3::new(
                (k as f64).sin(),
                (k as f64 * 1.7).cos(),
                (k as f64 * 0.3).sin(),
            ) * 3.0;
            let best = climb(k % tris.len(), &neighbours, &|f| value_of(p, &tris[f]));
            let brute = tris
                .iter()
                .map(|t| value_of(p, t))
                .fold(f64::NEG_INFINITY, f64::max);
            assert!(
                (value_of(p, &tris[best]) - brute).abs() <= 1e-12 * brute.abs(),
                "{p}"
            );
        }
    }
}

#[cfg(test)]
mod degenerate_sets {
    use proptest::prelude::*;

    use super::*;

    /// Whether integer points span a volume (exact: some 3 × 3 determinant
    /// of differences is non-zero).
    fn spans_volume(p: &[[i64; 3]]) -> bool {
        let d = |a: [i64; 3]| [a[0] - p[0][0], a[1] - p[0][1], a[2] - p[0][2]];
        p.iter().any(|&a| {
            p.iter().any(|&b| {
                p.iter().any(|&c| {
                    let (a, b, c) = (d(a), d(b), d(c));
                    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                        + a[2] * (b[0] * c[1] - b[1] * c[0])
                        != 0
                })
            })
        })
    }

    #[test]
    fn a_surface_winding_twice_fails_the_check() {
        // A bipyramid over a pentagram: closed, a sphere, every face facing
        // away from the centre, but it covers the directions twice.
        let mut hull: Vec<DVec3> = (0..5)
            .map(|i| {
                let t = core::f64::consts::TAU * f64::from(2 * i) / 5.0;
                DVec3::new(t.cos(), t.sin(), 0.0)
            })
            .collect();
        hull.extend([DVec3::Z, -DVec3::Z]);
        let triangles: Vec<[u32; 3]> = (0..5u32)
            .flat_map(|i| [[i, (i + 1) % 5, 5], [(i + 1) % 5, i, 6]])
            .collect();
        let all: Vec<usize> = (0..hull.len()).collect();
        let e = check_hull(&hull, &triangles, &all, &hull).unwrap_err();
        assert!(e.contains("winds 2"), "{e}");
    }

    #[test]
    fn a_lattice_set_that_folded_a_plane_gets_its_true_hull() {
        // Regression (found by the proptest below): replacing coplanar faces
        // folded a face plane over itself (one triangle facing inward, an
        // extra vertex outside the true hull), and the edge test could not
        // see a fold within one plane. The check now refuses inward faces,
        // and the strict policy gives the hull. Exact: Qhull on the integer
        // points gives 119/6 with 8 vertices.
        let lattice = [
            [2, 3, 3],
            [3, 3, 3],
            [1, 1, 0],
            [1, 0, 0],
            [3, 3, 0],
            [0, 0, 0],
            [0, 0, 0],
            [0, 0, 1],
            [0, 3, 0],
            [0, 3, 3],
            [0, 0, 0],
            [2, 0, 0],
            [3, 1, 3],
            [0, 0, 0],
        ];
        let stretch = DVec3::new(1.0, 1e-4, 1e-2);
        let rotation =
            DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 5.636402101045564);
        let points: Vec<DVec3> = lattice
            .iter()
            .map(|a| rotation * (DVec3::new(a[0] as f64, a[1] as f64, a[2] as f64) * stretch))
            .collect();
        let hull = convex_hull(&TriMesh::new(points, vec![[0, 1, 2]])).unwrap();
        // (A point on the hull's surface may stay a vertex: 9 here.)
        assert!(hull.vertices().len() >= 8);
        let volume = crate::MeshMoments::solid(&hull).zeroth;
        let exact = 119.0 / 6.0 * 1e-6;
        assert!((volume / exact - 1.0).abs() < 1e-9, "{volume} vs {exact}");
    }

    #[test]
    fn a_lattice_needle_gets_no_sliver_faces() {
        // Regression (found by the proptest below): three nearly collinear
        // points made a triangle 5e-13 high, whose plane rounding tilts so
        // far that a point 2e-4 m inside the needle lay "outside" it.
        let lattice = [
            [1, 1, 0],
            [2, 0, 3],
            [0, 1, 0],
            [2, 2, 1],
            [3, 2, 1],
            [1, 1, 2],
            [2, 2, 0],
            [3, 1, 0],
            [0, 3, 0],
            [3, 0, 0],
            [2, 0, 1],
            [2, 2, 0],
            [1, 3, 1],
            [0, 0, 1],
            [2, 0, 0],
            [0, 1, 3],
            [1, 0, 3],
            [0, 0, 3],
            [1, 3, 3],
            [2, 1, 2],
            [3, 2, 3],
            [0, 3, 3],
            [2, 3, 1],
            [0, 2, 2],
            [3, 3, 0],
        ];
        let stretch = DVec3::new(3.0, 1e-4, 1e-4);
        let rotation =
            DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 2.9626739640450066);
        let points: Vec<DVec3> = lattice
            .iter()
            .map(|a| rotation * (DVec3::new(a[0] as f64, a[1] as f64, a[2] as f64) * stretch))
            .collect();
        let hull = convex_hull(&TriMesh::new(points.clone(), vec![[0, 1, 2]])).unwrap();
        // Qhull on the integer points: 11 vertices, volume 74/3.
        assert_eq!(hull.vertices().len(), 11);
        for t in hull.triangles() {
            let [a, b, c] = hull.corners(*t);
            let n = (b - a).cross(c - a).normalize();
            for p in &points {
                assert!(n.dot(*p - a) < 1e-11, "{p} outside {t:?}");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        /// Points on a small integer lattice (many coplanar and collinear
        /// points, duplicates), stretched up to 10⁴ : 1 and rotated: the hull
        /// is built and passes its checks, or the set is flat and says so.
        #[test]
        fn lattice_sets_give_a_checked_hull_or_a_flat_error(
            lattice in prop::collection::vec(prop::array::uniform3(0i64..4), 4..120),
            stretch in prop::array::uniform3(prop::sample::select(vec![1.0, 1e-2, 1e-4, 3.0])),
            angle in 0.0f64..6.3,
        ) {
            let rotation = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), angle);
            let points: Vec<DVec3> = lattice
                .iter()
                .map(|a| rotation * (DVec3::new(a[0] as f64, a[1] as f64, a[2] as f64) * DVec3::from_array(stretch)))
                .collect();
            match convex_hull(&TriMesh::new(points.clone(), vec![[0, 1, 2]])) {
                Ok(hull) => {
                    prop_assert!(spans_volume(&lattice));
                    // Brute force: every point inside every face plane.
                    let size = DVec3::from_array(stretch).max_element() * 4.0;
                    for t in hull.triangles() {
                        let [a, b, c] = hull.corners(*t);
                        let n = (b - a).cross(c - a).normalize();
                        for p in &points {
                            prop_assert!(n.dot(*p - a) < 1e-9 * size, "{p} outside");
                        }
                    }
                    prop_assert!(hull.vertices().iter().all(|v| points.contains(v)));
                }
                Err(InertiaError::DegenerateHull { .. }) => prop_assert!(!spans_volume(&lattice)),
                Err(e) => prop_assert!(false, "{e}"),
            }
        }
    }
}
