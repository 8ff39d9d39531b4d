//! The surface of a [`ContactRequest`]: the shape rules, one place for
//! every client — which keys each shape needs and which it refuses.
//!
//! ```text
//! sphere     radius > 0                       (no normal, no semi_axes)
//! disk       radius > 0, normal ≠ 0            (no semi_axes)
//! ellipsoid  semi_axes a, b, c > 0             (no radius, no normal)
//! any        center, finite [default: 0]; the name one of sphere, disk, ellipsoid
//! ```
//!
//! The library's [`SphereContact`], [`DiskContact`] and
//! [`EllipsoidContact`] check the numbers once more; their refusal is the
//! problem of the key it is about.

use glam::DVec3;
use kreisel_dynamics::{ContactShape, DiskContact, EllipsoidContact, SphereContact};

use crate::contact_key::{ContactKey, ContactKeyProblem, Needs, NotFor, ShapeName};
use crate::contact_request::{ContactRequest, Fault, finite, needed, not_given, positive, refused};

impl<A: Clone> ContactRequest<A> {
    /// Where the shape is named (else the contact as a whole).
    pub(crate) fn shape_at(&self) -> &A {
        self.shape.as_ref().map_or(&self.contact, |(_, at)| at)
    }

    /// The surface from `shape`, `radius`, `center`, `normal`, `semi_axes`.
    pub(crate) fn shape(&self) -> Result<(ShapeName, ContactShape), Fault<A>> {
        let (given, at) = needed(&self.shape, ContactKey::Shape, Needs::Shape, &self.contact)?;
        let name: ShapeName = given.parse().map_err(|p| (at.clone(), p))?;
        let center = match &self.center {
            Some((c, at)) => finite(*c, ContactKey::Center, at)?,
            None => DVec3::ZERO,
        };
        if name != ShapeName::Ellipsoid {
            not_given(&self.semi_axes, ContactKey::SemiAxes, NotFor::OnlyEllipsoid)?;
        }
        let shape = match name {
            ShapeName::Sphere => {
                not_given(&self.normal, ContactKey::Normal, NotFor::OnlyDisk)?;
                SphereContact::try_new(self.radius()?, center)
                    .map(ContactShape::Sphere)
                    .map_err(refused(ContactKey::Shape, at))?
            }
            ShapeName::Disk => {
                let radius = self.radius()?;
                let key = ContactKey::Normal;
                let (axis, at) = needed(&self.normal, key, Needs::Shape, at)?;
                DiskContact::try_new(radius, center, finite(*axis, key, at)?)
                    .map(ContactShape::Disk)
                    .map_err(refused(key, at))?
            }
            ShapeName::Ellipsoid => {
                not_given(&self.radius, ContactKey::Radius, NotFor::Ellipsoid)?;
                not_given(&self.normal, ContactKey::Normal, NotFor::OnlyDisk)?;
                let key = ContactKey::SemiAxes;
                let (axes, at) = needed(&self.semi_axes, key, Needs::Shape, at)?;
                let axes = finite(*axes, key, at)?;
                if let Some(value) = axes.to_array().into_iter().find(|x| *x <= 0.0) {
                    return Err((at.clone(), ContactKeyProblem::NotPositive { key, value }));
                }
                EllipsoidContact::try_new(axes, center)
                    .map(ContactShape::Ellipsoid)
                    .map_err(refused(key, at))?
            }
        };
        Ok((name, shape))
    }

    /// The radius of a sphere or a disk: needed, positive and finite.
    fn radius(&self) -> Result<f64, Fault<A>> {
        let key = ContactKey::Radius;
        let (r, at) = needed(&self.radius, key, Needs::Shape, self.shape_at())?;
        positive(*r, key, at)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact_request::tests::{Change, request};
    use ContactKey as K;
    use ContactKeyProblem as P;

    #[test]
    fn each_shape_problem_points_at_its_key() {
        let not_for = |key, why| P::NotFor { key, why };
        let missing = |key, needs| P::Missing { key, needs };
        #[rustfmt::skip] // one case a line
        let cases: Vec<(&str, Change, &str, ContactKeyProblem)> = vec![
            ("cube", |_| {}, "shape", P::UnknownShape { name: "cube".into() }),
            ("sphere", |r| r.center = Some((DVec3::NAN, "center")), "center", P::NotFinite { key: K::Center }),
            ("sphere", |r| r.radius = None, "shape", missing(K::Radius, Needs::Shape)),
            ("disk", |r| r.radius = Some((-0.1, "radius")), "radius", P::NotPositive { key: K::Radius, value: -0.1 }),
            ("disk", |r| r.normal = None, "shape", missing(K::Normal, Needs::Shape)),
            ("sphere", |r| r.semi_axes = Some((DVec3::ONE, "semi_axes")), "semi_axes", not_for(K::SemiAxes, NotFor::OnlyEllipsoid)),
            ("sphere", |r| r.normal = Some((DVec3::Z, "normal")), "normal", not_for(K::Normal, NotFor::OnlyDisk)),
            ("ellipsoid", |r| r.radius = Some((0.1, "radius")), "radius", not_for(K::Radius, NotFor::Ellipsoid)),
            ("ellipsoid", |r| r.semi_axes = Some((DVec3::new(0.2, -0.03, 0.02), "semi_axes")), "semi_axes", P::NotPositive { key: K::SemiAxes, value: -0.03 }),
        ];
        for (shape, change, at, expected) in cases {
            let mut r = request(shape, "none");
            change(&mut r);
            assert_eq!(r.shape().map(|_| ()), Err((at, expected)), "{shape}");
        }
        // The library's own check: a disk's axis of length zero, at its key.
        let mut disk = request("disk", "none");
        disk.normal = Some((DVec3::ZERO, "normal"));
        let refused = disk.shape().map(|_| ()).unwrap_err();
        assert!(
            matches!(refused, ("normal", P::Library { key: K::Normal, .. })),
            "{refused:?}"
        );
        let made = request("ellipsoid", "none").shape().map(|(name, _)| name);
        assert_eq!(made, Ok(ShapeName::Ellipsoid));
    }
}
