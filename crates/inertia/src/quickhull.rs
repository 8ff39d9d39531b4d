//! Quickhull in 3-D with conflict lists, for points already in a round
//! (whitened) frame: coordinates in about `[-1, 1]`, so fixed tolerances are
//! relative ones.
//!
//! Each face keeps the points outside it (its conflict list); the face's
//! farthest point is added next, the faces it sees are found by a walk over
//! face neighbours, the horizon (the boundary of that region, checked to be
//! one simple cycle) is coned to the new point, and the seen faces' points
//! are handed to the new faces or dropped as inside. Time is about
//! `n log h` on random inputs, and stays near linear when every point is a
//! hull vertex (a finely tessellated sphere), where parry's quickhull 0.31
//! spends minutes (see `convex_hull.rs` for the figures).
//!
//! Tolerances make it robust enough, and the caller checks the result
//! independently (closed, outward, convex, containing every point):
//! - a point is *outside* a face only beyond [`OUTSIDE`]; points within it
//!   of the hull are dropped (they lie on the hull within `OUTSIDE`);
//! - which faces the new point *sees* is a [`Visibility`] policy. Coplanar
//!   faces are the hard case: replacing them keeps the seen region in one
//!   piece on a finely tessellated sphere but can fold a plane over itself
//!   on lattice-like sets; keeping them never folds but can split the seen
//!   region on the sphere (a dent of 8e-6 on the UV sphere). Neither wins
//!   everywhere, so the caller tries [`Visibility::Inclusive`] first and
//!   [`Visibility::Strict`] when its hull fails the check (measured: the
//!   proptest of `convex_hull.rs` on stretched integer lattices, the
//!   spheres of `tests/data/gen/hull_sphere.py`).

use glam::DVec3;

/// A point must be this far outside a face (whitened units) to be added;
/// more than [`SLIVER`] and [`SEEN`], so that an apex is never that close
/// to the hull and the face it was taken from sees it.
pub(crate) const OUTSIDE: f64 = 2e-10;

/// [`Visibility::Inclusive`]: a face is seen unless the point is this far
/// below its plane.
const COPLANAR: f64 = 1e-13;

/// [`Visibility::Inclusive`]: a new face must rise this far above its base
/// edge; a lower one would be a sliver whose plane rounding leaves undefined.
const SLIVER: f64 = 1e-10;

/// [`Visibility::Strict`]: a face is seen by a point this far above its
/// plane (so every new face rises at least this far above its base edge).
const SEEN: f64 = 1e-10;

/// Which faces a new hull point replaces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Visibility {
    /// Every face the point is above or (within [`COPLANAR`]) level with,
    /// and a nearly coplanar face on whose edge's line the point lies (so
    /// no sliver is made).
    Inclusive,
    /// Only the faces the point is more than [`SEEN`] above.
    Strict,
}

/// No face (a sentinel for a missing neighbour).
const NONE: u32 = u32::MAX;

/// One triangle of the hull under construction.
struct Face {
    /// Corners (indices into the points), counter-clockwise from outside.
    v: [u32; 3],
    /// The face across edge `v[e] → v[e + 1]`.
    adj: [u32; 3],
    /// Unit outward normal.
    n: DVec3,
    /// `n · x` on the face's plane.
    off: f64,
    /// The points outside this face (and no earlier one).
    outside: Vec<u32>,
    /// The farthest point of `outside`, and its distance.
    far: (u32, f64),
    /// Walk stamp: the apex step this face was last looked at in.
    stamp: u32,
    /// Seen from the current apex (valid when `stamp` is the current step).
    seen: bool,
    /// Still part of the hull.
    alive: bool,
}

impl Face {
    fn new(points: &[DVec3], v: [u32; 3]) -> Result<Self, String> {
        let [a, b, c] = v.map(|i| points[i as usize]);
        let n = (b - a).cross(c - a);
        let len = n.length();
        if len.is_nan() || len <= 0.0 {
            return Err(format!("face {v:?} has no area"));
        }
        let n = n / len;
        Ok(Self {
            v,
            adj: [NONE; 3],
            n,
            off: n.dot(a + b + c) / 3.0,
            outside: Vec::new(),
            far: (NONE, f64::NEG_INFINITY),
            stamp: 0,
            seen: false,
            alive: true,
        })
    }

    fn distance(&self, p: DVec3) -> f64 {
        self.n.dot(p) - self.off
    }

    /// Takes point `i` if it lies outside beyond [`OUTSIDE`].
    fn offer(&mut self, i: u32, p: DVec3) -> bool {
        let d = self.distance(p);
        if d > OUTSIDE {
            self.outside.push(i);
            if d > self.far.1 {
                self.far = (i, d);
            }
            true
        } else {
            false
        }
    }
}

/// The convex hull of `points[candidates]`: the hull's vertices (indices
/// into `points`) and its outward-wound triangles (indices into that list).
///
/// `Err` says why no hull was built (too few points off a plane, a horizon
/// that is no simple cycle); the caller reports it.
pub(crate) fn quickhull(
    points: &[DVec3],
    candidates: &[usize],
    visibility: Visibility,
) -> Result<(Vec<usize>, Vec<[u32; 3]>), String> {
    let index = |i: usize| u32::try_from(i).map_err(|_| "over 2³² points".to_string());
    let ids: Vec<u32> = candidates
        .iter()
        .map(|&i| index(i))
        .collect::<Result<_, _>>()?;
    let at = |i: u32| points[i as usize];
    let mut faces = simplex(points, &ids)?;
    let corners: Vec<u32> = faces.iter().flat_map(|f| f.v).collect();
    for &i in &ids {
        if !corners.contains(&i) {
            // The first face it is outside of takes it.
            let _ = faces.iter_mut().any(|f| f.offer(i, at(i)));
        }
    }
    let mut pending: Vec<u32> = (0..4).collect();
    let mut free: Vec<u32> = Vec::new();
    // Per vertex: (step, horizon edge starting there, its end).
    let mut starts = vec![(0u32, NONE, NONE); points.len()];
    let mut step = 0u32;
    let mut seen = Vec::new();
    let mut walk = Vec::new();
    let mut horizon: Vec<(u32, u32, u32)> = Vec::new();
    while let Some(f) = pending.pop() {
        let face = &faces[f as usize];
        if !face.alive || face.outside.is_empty() {
            continue;
        }
        step += 1;
        let apex = face.far.0;
        let p = at(apex);
        // The faces the apex sees, by a walk from `f`, and the horizon edges.
        seen.clear();
        horizon.clear();
        faces[f as usize].stamp = step;
        faces[f as usize].seen = true;
        seen.push(f);
        walk.push(f);
        while let Some(g) = walk.pop() {
            for e in 0..3 {
                let h = faces[g as usize].adj[e];
                let other = &mut faces[h as usize];
                let d = other.distance(p);
                let mut newly = false;
                if other.stamp != step {
                    other.stamp = step;
                    other.seen = match visibility {
                        Visibility::Inclusive => d > -COPLANAR,
                        Visibility::Strict => d > SEEN,
                    };
                    newly = other.seen;
                }
                if visibility == Visibility::Inclusive && !other.seen && d > -SLIVER {
                    // A cone face on this edge would be a sliver: the apex is
                    // (nearly) on the edge's line, beyond the edge (it is
                    // over `OUTSIDE` off the hull), and (nearly) in the plane
                    // of the face across, so replace that face too.
                    let v = faces[g as usize].v;
                    let (a, b) = (at(v[e]), at(v[(e + 1) % 3]));
                    let height = (p - a).cross(b - a).length() / (b - a).length();
                    newly = height.is_nan() || height < SLIVER;
                    faces[h as usize].seen = newly;
                }
                if newly {
                    seen.push(h);
                    walk.push(h);
                }
            }
        }
        for &g in &seen {
            for e in 0..3 {
                let h = faces[g as usize].adj[e];
                if !faces[h as usize].seen {
                    let v = faces[g as usize].v;
                    horizon.push((v[e], v[(e + 1) % 3], h));
                }
            }
        }
        // The horizon must be one simple cycle (the seen faces a disc).
        for (k, &(a, b, _)) in horizon.iter().enumerate() {
            let s = &mut starts[a as usize];
            if s.0 == step {
                return Err(format!("the horizon passes twice through point {a}"));
            }
            *s = (step, k as u32, b);
        }
        let mut v = horizon[0].0;
        for _ in 0..horizon.len() {
            let s = starts[v as usize];
            if s.0 != step {
                return Err(format!("the horizon is broken at point {v}"));
            }
            v = s.2;
        }
        if v != horizon[0].0 {
            return Err("the horizon is more than one cycle".into());
        }
        // Retire the seen faces, keeping their points.
        let mut orphans = Vec::new();
        for &g in &seen {
            let face = &mut faces[g as usize];
            face.alive = false;
            orphans.append(&mut face.outside);
            free.push(g);
        }
        // Cone the horizon to the apex.
        let mut new_ids = Vec::with_capacity(horizon.len());
        for &(a, b, _) in &horizon {
            let face = Face::new(points, [a, b, apex])?;
            let id = match free.pop() {
                Some(id) => {
                    faces[id as usize] = face;
                    id
                }
                None => {
                    faces.push(face);
                    index(faces.len() - 1)?
                }
            };
            new_ids.push(id);
        }
        for (k, &(a, b, h)) in horizon.iter().enumerate() {
            let id = new_ids[k];
            // Across `b → apex`: the new face whose horizon edge starts at `b`
            // (its edge 2, `apex → b`).
            let after = new_ids[starts[b as usize].1 as usize];
            faces[id as usize].adj[0] = h;
            faces[id as usize].adj[1] = after;
            let back = &mut faces[h as usize];
            let e = (0..3)
                .find(|&e| back.v[e] == b && back.v[(e + 1) % 3] == a)
                .ok_or("a horizon face lost its edge")?;
            back.adj[e] = id;
            faces[after as usize].adj[2] = id;
        }
        // Hand the orphans to the new faces (the apex itself is on the hull).
        for i in orphans {
            if i != apex {
                let q = at(i);
                let _ = new_ids.iter().any(|&g| faces[g as usize].offer(i, q));
            }
        }
        pending.extend(
            new_ids
                .iter()
                .filter(|&&g| !faces[g as usize].outside.is_empty()),
        );
    }
    // Number the vertices in use.
    let mut number = vec![NONE; points.len()];
    let mut vertices = Vec::new();
    let triangles = faces
        .iter()
        .filter(|f| f.alive)
        .map(|f| {
            f.v.map(|i| {
                let slot = &mut number[i as usize];
                if *slot == NONE {
                    *slot = vertices.len() as u32;
                    vertices.push(i as usize);
                }
                *slot
            })
        })
        .collect();
    Ok((vertices, triangles))
}

/// A starting tetrahedron, wound outward with neighbours linked: the
/// extremes along x, the point farthest from their line, the point farthest
/// from that plane.
fn simplex(points: &[DVec3], ids: &[u32]) -> Result<Vec<Face>, String> {
    let at = |i: u32| points[i as usize];
    let farthest = |score: &dyn Fn(DVec3) -> f64| {
        ids.iter()
            .map(|&i| (i, score(at(i))))
            .fold(
                (NONE, f64::NEG_INFINITY),
                |a, b| if b.1 > a.1 { b } else { a },
            )
    };
    let (a, _) = farthest(&|p| -p.x);
    let (b, _) = farthest(&|p| p.x);
    let (pa, pb) = (at(a), at(b));
    let axis = (pb - pa).normalize_or_zero();
    let (c, line) = farthest(&|p| (p - pa).reject_from_normalized(axis).length());
    let normal = axis.cross(at(c) - pa).normalize_or_zero();
    let (d, plane) = farthest(&|p| normal.dot(p - pa).abs());
    if [line, plane].iter().any(|&d| d.is_nan() || d <= OUTSIDE) {
        return Err("the points span no volume".into());
    }
    let centre = (pa + pb + at(c) + at(d)) / 4.0;
    let mut faces = [[a, b, c], [a, b, d], [a, c, d], [b, c, d]]
        .into_iter()
        .map(|v| {
            let face = Face::new(points, v)?;
            // Wind outward: the centre below the face.
            if face.distance(centre) > 0.0 {
                Face::new(points, [v[0], v[2], v[1]])
            } else {
                Ok(face)
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    for k in 0..4 {
        for e in 0..3 {
            let (u, w) = (faces[k].v[e], faces[k].v[(e + 1) % 3]);
            let across = (0..4).find(|&g| {
                g != k && (0..3).any(|x| faces[g].v[x] == w && faces[g].v[(x + 1) % 3] == u)
            });
            faces[k].adj[e] = across.ok_or("the starting tetrahedron is not closed")? as u32;
        }
    }
    Ok(faces)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xorshift in `[-1, 1)`.
    fn random(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        }
    }

    /// The hull of all `points`, checked by brute force: every point on the
    /// inner side of every face (within `OUTSIDE`), every face with area,
    /// every edge used once each way. Returns (vertex indices, volume).
    fn checked_hull(points: &[DVec3]) -> (Vec<usize>, f64) {
        let all: Vec<usize> = (0..points.len()).collect();
        let strict = checked(points, quickhull(points, &all, Visibility::Strict).unwrap());
        let inclusive = checked(
            points,
            quickhull(points, &all, Visibility::Inclusive).unwrap(),
        );
        assert!((strict.1 / inclusive.1 - 1.0).abs() < 1e-12);
        inclusive
    }

    fn checked(points: &[DVec3], hull: (Vec<usize>, Vec<[u32; 3]>)) -> (Vec<usize>, f64) {
        let (vertices, triangles) = hull;
        let mut edges = std::collections::HashSet::new();
        let mut volume = 0.0;
        for t in &triangles {
            let [a, b, c] = t.map(|i| points[vertices[i as usize]]);
            let n = (b - a).cross(c - a);
            assert!(n.length() > 0.0, "{t:?}");
            let n = n.normalize();
            for (k, p) in points.iter().enumerate() {
                assert!(n.dot(*p - a) <= OUTSIDE, "point {k} outside face {t:?}");
            }
            for e in 0..3 {
                assert!(edges.insert((t[e], t[(e + 1) % 3])), "{t:?}");
            }
            volume += a.dot(b.cross(c)) / 6.0;
        }
        for &(a, b) in &edges {
            assert!(edges.contains(&(b, a)), "open at {a}-{b}");
        }
        assert_eq!(2 * vertices.len(), triangles.len() + 4, "V − E + F ≠ 2");
        (vertices, volume)
    }

    #[test]
    fn random_ball_hull_contains_every_point() {
        let mut r = random(7);
        let points: Vec<DVec3> = (0..5000)
            .map(|_| DVec3::new(r(), r(), r()))
            .filter(|p| p.length() <= 1.0)
            .collect();
        let (vertices, volume) = checked_hull(&points);
        assert!(vertices.len() > 50 && vertices.len() < points.len() / 4);
        // Inscribed in the unit ball, and most of it.
        let ball = 4.0 / 3.0 * core::f64::consts::PI;
        assert!(volume < ball && volume > 0.8 * ball, "{volume}");
    }

    #[test]
    fn points_in_convex_position_plus_inner_points_give_exactly_those_vertices() {
        // 2000 random directions on the unit sphere (all hull vertices) and
        // 2000 points inside the sphere of radius 0.9 (none are): the hull's
        // vertex set is exactly the sphere's points.
        let mut r = random(11);
        let mut points = Vec::new();
        while points.len() < 2000 {
            let p = DVec3::new(r(), r(), r());
            if p.length() > 0.1 && p.length() <= 1.0 {
                points.push(p.normalize());
            }
        }
        while points.len() < 4000 {
            let p = DVec3::new(r(), r(), r());
            if p.length() <= 1.0 {
                points.push(0.9 * p);
            }
        }
        let (mut vertices, _) = checked_hull(&points);
        vertices.sort_unstable();
        assert_eq!(vertices, (0..2000).collect::<Vec<_>>());
    }

    #[test]
    fn a_lattice_cube_is_the_cube() {
        // 11³ lattice points: every face holds 121 coplanar points, every
        // edge 11 collinear ones. The hull is the cube [-1, 1]³ exactly.
        let points: Vec<DVec3> = (0..1331)
            .map(|i| {
                let c = |k: usize| (k % 11) as f64 / 5.0 - 1.0;
                DVec3::new(c(i), c(i / 11), c(i / 121))
            })
            .collect();
        let (vertices, volume) = checked_hull(&points);
        assert!((volume - 8.0).abs() < 1e-13, "{volume}");
        // The corners are hull vertices; points inside faces are not needed.
        for v in &vertices {
            let p = points[*v];
            assert!(p.abs().max_element() == 1.0, "{p}");
        }
        for corner in 0..8 {
            let p = DVec3::new(
                [-1.0, 1.0][corner & 1],
                [-1.0, 1.0][(corner >> 1) & 1],
                [-1.0, 1.0][corner >> 2],
            );
            assert!(vertices.iter().any(|&v| points[v] == p), "{p}");
        }
    }

    #[test]
    fn flat_points_are_refused() {
        let mut r = random(3);
        let points: Vec<DVec3> = (0..100).map(|_| DVec3::new(r(), r(), 0.0)).collect();
        let all: Vec<usize> = (0..points.len()).collect();
        for visibility in [Visibility::Inclusive, Visibility::Strict] {
            assert!(quickhull(&points, &all, visibility).is_err());
        }
    }
}
