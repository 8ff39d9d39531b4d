//! Exact integration of volume and surface moments over triangle meshes:
//! one signed tetrahedron per triangle, summed about a point of the mesh.

use glam::{DMat3, DVec3};

use crate::mass_properties::check_positive;
use crate::parallel::{map_ranges, threads_for};
use crate::solid_kernel::{Sums, add_in_order, solid_sums};
use crate::{InertiaError, KernelError, MassProperties, SolidKernel, TriMesh};

/// Triangles summed into one partial sum before it is added to the total,
/// so rounding errors grow like `n/B + B` instead of `n`.
const BLOCK: usize = 512;

/// The zeroth, first and second moments of a mesh's volume (or surface)
/// about a reference point `origin`.
///
/// ```text
/// zeroth = ∫ dV,   first = ∫ r dV,   second = ∫ r rᵀ dV,   r = x − origin
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshMoments {
    /// The point the moments are taken about (a point of the mesh).
    pub origin: DVec3,
    /// Volume (m³) or area (m²).
    pub zeroth: f64,
    /// First moment `∫ r`.
    pub first: DVec3,
    /// Second moment `∫ r rᵀ` (symmetric).
    pub second: DMat3,
}

/// Accumulates one triangle's weight `w` and corners (relative to the origin).
#[inline(always)]
fn accumulate(acc: &mut Sums, w: f64, a: DVec3, b: DVec3, c: DVec3) {
    let s = a + b + c;
    let sq = |i: usize, j: usize| s[i] * s[j] + a[i] * a[j] + b[i] * b[j] + c[i] * c[j];
    acc[0] += w;
    acc[1] += w * s.x;
    acc[2] += w * s.y;
    acc[3] += w * s.z;
    acc[4] += w * sq(0, 0);
    acc[5] += w * sq(1, 1);
    acc[6] += w * sq(2, 2);
    acc[7] += w * sq(0, 1);
    acc[8] += w * sq(0, 2);
    acc[9] += w * sq(1, 2);
}

/// A reference point of the mesh: the mean of its vertices (each vertex
/// taken relative to the first, so the mean itself loses no digits).
fn reference_point(mesh: &TriMesh) -> DVec3 {
    let v = mesh.vertices();
    let first = v[0];
    let sum: DVec3 = v.iter().map(|&x| x - first).sum();
    first + sum / v.len() as f64
}

/// Sums `weight(a, b, c)` and the moments over all triangles, blockwise,
/// on the machine's cores from [`crate::parallel::PARALLEL_MIN`] triangles
/// (the same bits on any number of threads: see [`integrate_on`]).
fn integrate(mesh: &TriMesh, weight: impl Fn(DVec3, DVec3, DVec3) -> f64 + Sync) -> (DVec3, Sums) {
    let threads = threads_for(mesh.triangles().len());
    integrate_on(mesh, weight, threads)
}

/// [`integrate`] on at most `threads` threads: each block of [`BLOCK`]
/// triangles is summed alone and the blocks' sums are added in block order.
fn integrate_on(
    mesh: &TriMesh,
    weight: impl Fn(DVec3, DVec3, DVec3) -> f64 + Sync,
    threads: usize,
) -> (DVec3, Sums) {
    let origin = reference_point(mesh);
    let v = mesh.vertices();
    let triangles = mesh.triangles();
    let partials = map_ranges(triangles.len(), threads, BLOCK, |r| {
        triangles[r]
            .chunks(BLOCK)
            .map(|block| {
                let mut acc = [0.0; 10];
                for &[i, j, k] in block {
                    let a = v[i as usize] - origin;
                    let b = v[j as usize] - origin;
                    let c = v[k as usize] - origin;
                    accumulate(&mut acc, weight(a, b, c), a, b, c);
                }
                acc
            })
            .collect::<Vec<Sums>>()
    });
    (origin, add_in_order(partials.iter().flatten()))
}

/// A triangle's weight in [`MeshMoments::shell`]: `|n| = 2A`.
fn doubled_area(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    (b - a).cross(c - a).length()
}

fn moments(origin: DVec3, sums: &Sums, zeroth: f64, first: f64, second: f64) -> MeshMoments {
    let s = |k: usize| sums[k] * second;
    MeshMoments {
        origin,
        zeroth: sums[0] * zeroth,
        first: DVec3::new(sums[1], sums[2], sums[3]) * first,
        second: DMat3::from_cols(
            DVec3::new(s(4), s(7), s(8)),
            DVec3::new(s(7), s(5), s(9)),
            DVec3::new(s(8), s(9), s(6)),
        ),
    }
}

impl MeshMoments {
    /// Volume moments of a closed, outward-wound mesh (the divergence
    /// theorem as one signed tetrahedron per triangle; Tonon, J. Math.
    /// Stat. 1:8 (2005); Kallay, J. Graphics Tools 11(2) (2006)).
    ///
    /// ```text
    /// per triangle (a, b, c), relative to the origin:  d = a · (b × c),  s = a + b + c
    /// ∫ dV = Σ d/6,   ∫ rᵢ dV = Σ d sᵢ/24,   ∫ rᵢ rⱼ dV = Σ d (sᵢ sⱼ + aᵢaⱼ + bᵢbⱼ + cᵢcⱼ)/120
    /// ```
    ///
    /// The origin is the vertex mean, so a part far from the coordinate
    /// origin loses no digits (`a − origin` is exact for vertices within a
    /// factor two of it). Orientation and closedness are not checked here.
    /// The sums are taken in the mesh's units as given; for a mesh far
    /// beyond `2^±64` m across, [`crate::mesh_mass_properties`] integrates
    /// in the mesh's own power-of-two unit and says when a result leaves f64.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::{MeshMoments, TriMesh};
    /// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    /// let tet = TriMesh::new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
    /// let m = MeshMoments::solid(&tet);
    /// assert!((m.zeroth - 1.0 / 6.0).abs() < 1e-16);
    /// # let c = m.origin + m.first / m.zeroth;
    /// # assert!((c - DVec3::splat(0.25)).length() < 1e-15);
    /// ```
    pub fn solid(mesh: &TriMesh) -> Self {
        Self::solid_on(mesh, SolidKernel::active())
    }

    /// [`MeshMoments::solid`] by a chosen build of its kernel (for tests
    /// and benchmarks: every build gives the same bits).
    ///
    /// # Errors
    /// [`KernelError::Unsupported`] if this CPU cannot run the build.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::{MeshMoments, SolidKernel, TriMesh};
    /// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    /// let tet = TriMesh::new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
    /// let portable = MeshMoments::solid_with(&tet, SolidKernel::Portable)?;
    /// assert_eq!(portable, MeshMoments::solid(&tet));
    /// # Ok::<(), kreisel_inertia::KernelError>(())
    /// ```
    pub fn solid_with(mesh: &TriMesh, kernel: SolidKernel) -> Result<Self, KernelError> {
        Ok(Self::solid_on(mesh, kernel.check()?))
    }

    /// [`MeshMoments::solid`] by `kernel`, which this CPU runs.
    fn solid_on(mesh: &TriMesh, kernel: SolidKernel) -> Self {
        let origin = reference_point(mesh);
        let sums = solid_sums(mesh.vertices(), origin, mesh.triangles(), kernel);
        moments(origin, &sums, 1.0 / 6.0, 1.0 / 24.0, 1.0 / 120.0)
    }

    /// Surface moments of a mesh (open or closed, any winding): the mesh as a
    /// thin shell of unit areal density.
    ///
    /// ```text
    /// per triangle: A = |(b − a) × (c − a)|/2
    /// ∫ dA = Σ A,   ∫ rᵢ dA = Σ A sᵢ/3,   ∫ rᵢ rⱼ dA = Σ A (sᵢ sⱼ + aᵢaⱼ + bᵢbⱼ + cᵢcⱼ)/12
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::{MeshMoments, TriMesh};
    /// let square = TriMesh::new(
    ///     vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
    ///     vec![[0, 1, 2], [0, 2, 3]],
    /// );
    /// let m = MeshMoments::shell(&square);
    /// assert!((m.zeroth - 1.0).abs() < 1e-16);
    /// ```
    pub fn shell(mesh: &TriMesh) -> Self {
        let (origin, sums) = integrate(mesh, doubled_area);
        // A = |n|/2:  zeroth Σ|n|/2,  first Σ|n| s/6,  second Σ|n| (…)/24.
        moments(origin, &sums, 0.5, 1.0 / 6.0, 1.0 / 24.0)
    }

    /// Mass properties of the integrated region at uniform `density` (kg/m³
    /// for volumes, kg/m² for surfaces).
    ///
    /// ```text
    /// m = ρ ∫dV,   c = origin + ∫r/∫dV,   S = ∫r rᵀ − ∫dV · c̃ c̃ᵀ  (c̃ = c − origin),   I = ρ (tr S · E − S)
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NonPositive`] for a density that is not positive and
    /// finite; [`InertiaError::ZeroVolume`] when the region has no positive
    /// volume (or area), e.g. an inside-out or open mesh;
    /// [`InertiaError::NotRepresentable`] for an infinite one; and the checks of
    /// [`MassProperties::try_new`].
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::{MeshMoments, TriMesh};
    /// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    /// let tet = TriMesh::new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
    /// let p = MeshMoments::solid(&tet).mass_properties(6.0)?;
    /// assert!((p.mass - 1.0).abs() < 1e-15);
    /// // Corner tetrahedron, mass 1: σ² = 1/10 − 1/16 = 3/80 per axis, so I_xx = 2 · 3/80.
    /// assert!((p.inertia.x_axis.x - 0.075).abs() < 1e-15);
    /// // covariance 1/20 − 1/16 = −1/80, so I_xy = +1/80
    /// assert!((p.inertia.x_axis.y - 0.0125).abs() < 1e-15);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn mass_properties(&self, density: f64) -> Result<MassProperties, InertiaError> {
        check_positive("density", density)?;
        // Also refuses NaN.
        if self.zeroth.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
            return Err(InertiaError::ZeroVolume);
        }
        if !self.zeroth.is_finite() {
            return Err(InertiaError::NotRepresentable {
                quantity: "volume",
                value: self.zeroth,
            });
        }
        let (c, inertia) = self.central(density);
        Ok(MassProperties::try_new(
            density * self.zeroth,
            self.origin + c,
            inertia,
        )?)
    }

    /// The centre of mass relative to the origin, and the inertia tensor
    /// about it at uniform `density`, of a region with a positive volume.
    ///
    /// ```text
    /// c̃ = ∫r/∫dV,   S = ∫r rᵀ − ∫dV · c̃ c̃ᵀ,   I = ρ (tr S · E − S)
    /// ```
    pub(crate) fn central(&self, density: f64) -> (DVec3, DMat3) {
        let c = self.first / self.zeroth;
        let outer = DMat3::from_cols(c * c.x, c * c.y, c * c.z);
        let s = self.second - outer * self.zeroth;
        let trace = s.x_axis.x + s.y_axis.y + s.z_axis.z;
        (c, (DMat3::IDENTITY * trace - s) * density)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::tri_mesh::box_mesh;

    #[test]
    fn box_matches_closed_form_far_from_origin() {
        let size = DVec3::new(1.0, 2.0, 3.0);
        let exact = MassProperties::solid_box(2.0, size).unwrap();
        for centre in [DVec3::ZERO, DVec3::new(1e6, -2e6, 3e6), DVec3::splat(1e9)] {
            let mesh = box_mesh(centre - size / 2.0, centre + size / 2.0);
            let p = MeshMoments::solid(&mesh).mass_properties(2.0).unwrap();
            assert!(
                (p.mass - exact.mass).abs() <= 1e-14 * exact.mass,
                "{centre}"
            );
            assert!((p.center_of_mass - centre).length() <= 1e-15 * centre.length().max(1.0));
            let err = (p.inertia - exact.inertia)
                .to_cols_array()
                .iter()
                .fold(0.0_f64, |a, v| a.max(v.abs()));
            assert!(err <= 1e-14 * exact.inertia.z_axis.z, "{centre}: {err:e}");
        }
    }

    #[test]
    fn shell_of_box_is_sum_of_faces() {
        // Unit cube shell: 6 faces of area 1; I_xx = 2 faces ⟂ x (1/6 each) + 4 faces ∥ x (1/12 + 1/4 each) = 2/6 + 4/3 = 5/3.
        let mesh = box_mesh(DVec3::ZERO, DVec3::ONE);
        let p = MeshMoments::shell(&mesh).mass_properties(1.0).unwrap();
        assert!((p.mass - 6.0).abs() < 1e-15);
        assert!((p.center_of_mass - DVec3::splat(0.5)).length() < 1e-15);
        assert!((p.inertia.x_axis.x - 5.0 / 3.0).abs() < 1e-15);
        assert!(p.inertia.x_axis.y.abs() < 1e-15);
    }

    #[test]
    fn inside_out_mesh_has_no_volume() {
        let mesh = box_mesh(DVec3::ZERO, DVec3::ONE);
        let (v, t) = mesh.into_parts();
        let flipped = TriMesh::new(v, t.into_iter().map(|[a, b, c]| [a, c, b]).collect());
        assert!(matches!(
            MeshMoments::solid(&flipped).mass_properties(1.0),
            Err(InertiaError::ZeroVolume)
        ));
    }

    /// The shell's sums on any number of threads are those of one thread
    /// adding block after block (as before they were parallel).
    #[test]
    fn shell_sums_do_not_depend_on_the_thread_count() {
        let v: Vec<DVec3> = (0..2000)
            .map(|i| {
                let t = f64::from(i);
                DVec3::new((0.37 * t).sin(), (1.3 * t).cos(), 1e3 + (0.71 * t).sin())
            })
            .collect();
        let tris: Vec<[u32; 3]> = (0..4321u32)
            .map(|i| [i % 2000, (7 * i + 1) % 2000, (13 * i + 5) % 2000])
            .collect();
        let mesh = TriMesh::new(v, tris);
        let origin = reference_point(&mesh);
        let v = mesh.vertices();
        let mut one = [0.0; 10];
        for block in mesh.triangles().chunks(BLOCK) {
            let mut acc = [0.0; 10];
            for &[i, j, k] in block {
                let (a, b, c) = (
                    v[i as usize] - origin,
                    v[j as usize] - origin,
                    v[k as usize] - origin,
                );
                accumulate(&mut acc, doubled_area(a, b, c), a, b, c);
            }
            for (t, p) in one.iter_mut().zip(acc) {
                *t += p;
            }
        }
        for threads in [1, 2, 3, 5, 64] {
            let (o, many) = integrate_on(&mesh, doubled_area, threads);
            assert_eq!(o, origin);
            assert_eq!(many.map(f64::to_bits), one.map(f64::to_bits), "{threads}");
        }
    }
}
