//! Where a body on the table starts, as the scene layer fills it in and
//! reports it: the height at which it touches when no `position` is
//! given, and the contact that Painlevé's case at the start is about
//! (shared by the scene file and Python's `World.add_body`).

use glam::{DQuat, DVec3};
use kreisel_dynamics::TableContact;

/// A contact closer to the table than this at the start touches it, m.
const TOUCHING_GAP: f64 = 1e-12;

/// The centre of mass above the origin at the height where the lowest of
/// `contacts` touches the table at attitude `q` (normalised): a body on
/// the table's default `position`.
///
/// ```text
/// x = (0, 0, max_c −(R(q) r_c)·e_z)     r_c: the contact point of shape c from the centre of mass
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{ContactLaw, ContactShape, SphereContact, TableContact};
/// use kreisel_scene::table_start::touching;
/// let sphere = SphereContact::try_new(0.1, DVec3::ZERO).unwrap();
/// let ball = TableContact { shape: ContactShape::Sphere(sphere), law: ContactLaw::new(0.3) };
/// assert_eq!(touching(&[ball], DQuat::IDENTITY), DVec3::new(0.0, 0.0, 0.1));
/// ```
pub fn touching(contacts: &[TableContact], q: DQuat) -> DVec3 {
    let height = contacts
        .iter()
        .map(|c| -c.shape.contact_from_com_world(q).z)
        .fold(f64::NEG_INFINITY, f64::max);
    DVec3::new(0.0, 0.0, height)
}

/// The contact of a body on the table (centre of mass at `position`,
/// attitude `q`) that Painlevé's case at its start is about: the first
/// that touches the table with friction, else the first; and its `mu`
/// (NaN without contacts).
///
/// ```text
/// first c with μ_c > 0 and z + (R(q̂) r_c)·e_z ≤ 1e-12 m
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{ContactLaw, ContactShape, SphereContact, TableContact};
/// use kreisel_scene::table_start::sliding_at_start;
/// let ball = |z: f64, mu: f64| TableContact {
///     shape: ContactShape::Sphere(SphereContact::try_new(0.1, DVec3::new(0.0, 0.0, z)).unwrap()),
///     law: ContactLaw::new(mu),
/// };
/// // The second ball hangs lower: it touches, the first does not.
/// let contacts = [ball(0.0, 0.3), ball(-0.05, 0.5)];
/// assert_eq!(sliding_at_start(&contacts, DVec3::new(0.0, 0.0, 0.15), DQuat::IDENTITY), (1, 0.5));
/// ```
pub fn sliding_at_start(contacts: &[TableContact], position: DVec3, q: DQuat) -> (usize, f64) {
    let touching_with_friction = |c: &TableContact| {
        let gap = position.z + c.shape.contact_from_com_world(q.normalize()).z;
        c.law.mu() > 0.0 && gap <= TOUCHING_GAP
    };
    let index = contacts
        .iter()
        .position(touching_with_friction)
        .unwrap_or(0);
    (index, contacts.get(index).map_or(f64::NAN, |c| c.law.mu()))
}
