//! A body as its user gives it, key by key, checked and added to a
//! [`World`] in one place: the scene file's `[[body]]` table
//! (`body_keys.rs`) and Python's `World.add_body` both fill in a
//! [`BodyRequest`] and call [`BodyRequest::add_to`].
//!
//! Each value comes with where it was given (`A`: a span of the scene's
//! text, or nothing for a Python keyword). A problem is a typed
//! [`BodyKeyProblem`] at the place of the key it is about; the client
//! words it in its own key names (`` `inertia_tensor` `` in a scene,
//! `inertia` in Python) — the checks are here, the messages there.
//!
//! ```text
//! inertia:  exactly one of moments, tensor, mesh (the client's keys)
//! attitude: a quaternion w, x, y, z normalised (not zero), or a rotation as given
//! support:  free · pivot (no velocity) · on the ground (one contact) · on the table
//!           (no applied loads; position defaults to touching) — pivot and contacts exclude each other
//! then the library's own checks (Body::try_build, World::add), each named by its key
//! ```

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{Body, BodyId, DynamicsError, Friction, Inputs, TableContact, World};
use kreisel_inertia::MassProperties;
use kreisel_kinematics::try_normalize_quat;

use crate::body_key::{BodyKey, BodyKeyError, BodyKeyProblem, Given};
use crate::contact_list::Contacts;
use crate::table_start::{sliding_at_start, touching};

/// The inertia as given.
#[derive(Debug, Clone)]
pub enum Inertia {
    /// Principal moments (body axes = principal axes).
    Moments(DVec3),
    /// The tensor about the centre of mass in body axes, rows.
    Tensor([[f64; 3]; 3]),
    /// Mass properties computed already (a mesh's), their own mass.
    Properties(MassProperties),
}

/// The attitude as given.
#[derive(Debug, Clone, Copy)]
pub enum Attitude {
    /// A quaternion `[w, x, y, z]`, normalised here (any non-zero length).
    Quaternion([f64; 4]),
    /// A rotation computed already (from Euler angles), taken as it is.
    Rotation(DQuat),
}

/// Everything a user gives of one body.
#[derive(Debug, Clone)]
pub struct BodyRequest<A> {
    /// Where the body is given as a whole.
    pub body: A,
    /// The mass (none with [`Inertia::Properties`]).
    pub mass: Given<f64, A>,
    /// The inertia and its key ([`BodyRequest::one_inertia`] picks it).
    pub inertia: (BodyKey, Inertia, A),
    /// The attitude (identity without).
    pub attitude: Given<Attitude, A>,
    /// The angular velocity in body axes (zero without).
    pub omega_body: Given<DVec3, A>,
    /// The centre of mass (the origin without; touching, on the table).
    pub position: Given<DVec3, A>,
    /// Its velocity (zero without).
    pub velocity: Given<DVec3, A>,
    /// A fixed pivot in body axes.
    pub pivot: Given<DVec3, A>,
    /// Torque, world axes.
    pub torque: Given<DVec3, A>,
    /// Torque, body axes.
    pub torque_body: Given<DVec3, A>,
    /// Force through the centre of mass, world axes.
    pub force: Given<DVec3, A>,
    /// Angular damping, N m s (≥ 0).
    pub angular_damping: Given<f64, A>,
    /// The contacts, checked key by key by the client.
    pub contacts: Given<Contacts, A>,
}

impl<A: Clone> BodyRequest<A> {
    /// The one inertia key of those `given` (key and where, in the order
    /// the client reads them).
    ///
    /// # Errors
    /// [`BodyKeyProblem::NoInertia`] at `body` when none is given,
    /// [`BodyKeyProblem::TwoInertias`] at the second when two are.
    ///
    /// ```
    /// use kreisel_scene::body_key::{BodyKey, BodyKeyProblem};
    /// use kreisel_scene::body_request::BodyRequest;
    /// assert_eq!(BodyRequest::one_inertia(&[(BodyKey::Tensor, 3)], 1), Ok((BodyKey::Tensor, 3)));
    /// let e = BodyRequest::one_inertia(&[(BodyKey::Moments, 2), (BodyKey::Mesh, 5)], 1).unwrap_err();
    /// assert_eq!((e.at, e.problem), (5, BodyKeyProblem::TwoInertias { first: BodyKey::Moments, second: BodyKey::Mesh }));
    /// ```
    pub fn one_inertia(given: &[(BodyKey, A)], body: A) -> Result<(BodyKey, A), BodyKeyError<A>> {
        match given {
            [] => Err(BodyKeyError {
                at: body,
                problem: BodyKeyProblem::NoInertia,
            }),
            [one] => Ok(one.clone()),
            [(first, _), (second, at), ..] => Err(BodyKeyError {
                at: at.clone(),
                problem: BodyKeyProblem::TwoInertias {
                    first: *first,
                    second: *second,
                },
            }),
        }
    }

    /// Checks the body and adds it to `world`: its id.
    ///
    /// # Errors
    /// The first problem found, at the key it is about (see the module
    /// docs for the order of the checks).
    pub fn add_to(self, world: &mut World) -> Result<BodyId, BodyKeyError<A>> {
        let body = self.body.clone();
        let fail = |at: &A, problem| BodyKeyError {
            at: at.clone(),
            problem,
        };
        let (inertia_key, inertia, inertia_at) = &self.inertia;
        let inertia_error = |error| {
            fail(
                inertia_at,
                BodyKeyProblem::Library {
                    key: *inertia_key,
                    error,
                },
            )
        };
        let builder = match (inertia, &self.mass) {
            (Inertia::Properties(props), _) => Body::from_mass_properties(*props),
            (_, None) => return Err(fail(&body, BodyKeyProblem::MissingMass)),
            (_, Some((m, at))) if !(m.is_finite() && *m > 0.0) => {
                let problem = BodyKeyProblem::NotPositive {
                    key: BodyKey::Mass,
                    value: *m,
                };
                return Err(fail(at, problem));
            }
            (Inertia::Moments(moments), Some((mass, _))) => {
                Body::from_principal_moments(*mass, *moments)
            }
            (Inertia::Tensor(rows), Some((mass, _))) => {
                let tensor = DMat3::from_cols_array_2d(rows).transpose();
                let props = MassProperties::try_new(*mass, DVec3::ZERO, tensor)
                    .map_err(|e| inertia_error(DynamicsError::from(e)))?;
                Body::from_mass_properties(props)
            }
        };
        // At rest, identity attitude, free: only the inertia can be refused.
        builder.clone().try_build().map_err(inertia_error)?;
        let attitude = match &self.attitude {
            None => DQuat::IDENTITY,
            Some((Attitude::Rotation(q), _)) => *q,
            Some((Attitude::Quaternion([w, x, y, z]), at)) => {
                try_normalize_quat(DQuat::from_xyzw(*x, *y, *z, *w))
                    .map_err(|_| fail(at, BodyKeyProblem::NotAQuaternion))?
            }
        };
        let value = |given: &Given<DVec3, A>| given.as_ref().map_or(DVec3::ZERO, |(v, _)| *v);
        let omega = value(&self.omega_body);
        let position = value(&self.position);
        let velocity = value(&self.velocity);
        let loads = [
            (BodyKey::Torque, &self.torque),
            (BodyKey::TorqueBody, &self.torque_body),
            (BodyKey::Force, &self.force),
        ];
        let first_load = loads
            .iter()
            .find_map(|(key, v)| v.as_ref().map(|(_, at)| (*key, at.clone())))
            .or_else(|| {
                let (_, at) = self.angular_damping.as_ref()?;
                Some((BodyKey::AngularDamping, at.clone()))
            });
        let mut inputs = Inputs::default()
            .with_torque_world(value(&self.torque))
            .with_torque_body(value(&self.torque_body))
            .with_force_world(value(&self.force));
        if let Some((c, at)) = &self.angular_damping {
            if !(c.is_finite() && *c >= 0.0) {
                return Err(fail(at, BodyKeyProblem::Damping { value: *c }));
            }
            inputs = inputs.with_angular_damping(*c);
        }
        let builder = builder.world_from_body(attitude).omega_body(omega);
        let mut table: Option<(Vec<TableContact>, DVec3)> = None;
        let builder = match (&self.contacts, &self.pivot) {
            (Some(_), Some((_, at))) => return Err(fail(at, BodyKeyProblem::PivotWithContacts)),
            (Some((Contacts::Table(contacts), _)), None) => {
                if let Some((key, at)) = &first_load {
                    return Err(fail(at, BodyKeyProblem::LoadsOnTable { key: *key }));
                }
                let position = match &self.position {
                    Some(_) => position,
                    None => touching(contacts, attitude),
                };
                table = Some((contacts.clone(), position));
                builder.on_table(position, velocity, contacts)
            }
            (Some((Contacts::Ground(contacts), _)), None) => {
                let first = contacts.first;
                if let Some((_, at)) = &self.velocity {
                    if first.friction == Friction::Rolling {
                        return Err(fail(at, BodyKeyProblem::VelocityWithRolling));
                    }
                    if velocity.z != 0.0 {
                        let problem = BodyKeyProblem::VelocityNotHorizontal { vz: velocity.z };
                        return Err(fail(at, problem));
                    }
                }
                builder
                    .on_ground_at(
                        first.shape,
                        first.friction,
                        position.truncate(),
                        velocity.truncate(),
                    )
                    .other_contacts(&contacts.others)
            }
            (None, Some((pivot, _))) => {
                if let Some((_, at)) = &self.velocity {
                    return Err(fail(at, BodyKeyProblem::VelocityWithPivot));
                }
                builder.pivot(*pivot, position)
            }
            (None, None) => builder.free(position, velocity),
        };
        let at_key = |key: BodyKey| -> A {
            let given = match key {
                BodyKey::Omega => self.omega_body.as_ref().map(|(_, a)| a),
                BodyKey::Position => self.position.as_ref().map(|(_, a)| a),
                BodyKey::Velocity => self.velocity.as_ref().map(|(_, a)| a),
                BodyKey::Pivot => self.pivot.as_ref().map(|(_, a)| a),
                BodyKey::Contacts => self.contacts.as_ref().map(|(_, a)| a),
                _ => None,
            };
            given.unwrap_or(&body).clone()
        };
        let library = |key: BodyKey, error| BodyKeyError {
            at: at_key(key),
            problem: BodyKeyProblem::Library { key, error },
        };
        let built = builder.try_build().map_err(|e| match e {
            DynamicsError::InvalidState { .. } => library(BodyKey::Omega, e),
            other => inertia_error(other),
        })?;
        let built = built
            .with_inputs(inputs)
            .map_err(|e| library(BodyKey::Body, e))?;
        let contacts_given = self.contacts.is_some();
        let id = world.add(built).map_err(|e| match e {
            DynamicsError::OtherContactTouching { contact, gap } if contacts_given => {
                BodyKeyError {
                    at: at_key(BodyKey::Contacts),
                    problem: BodyKeyProblem::WatchedTouching {
                        index: contact,
                        gap,
                    },
                }
            }
            DynamicsError::BodyInsideTable { contact, gap } if contacts_given => BodyKeyError {
                at: at_key(BodyKey::Position),
                problem: BodyKeyProblem::InsideTable {
                    contact,
                    gap,
                    position_given: self.position.is_some(),
                },
            },
            e @ DynamicsError::ContactIndeterminate { .. } if contacts_given => {
                let (laws, start) = table
                    .as_ref()
                    .map_or((&[][..], DVec3::ZERO), |(c, p)| (c.as_slice(), *p));
                let (contact, mu) = sliding_at_start(laws, start, attitude);
                BodyKeyError {
                    at: at_key(BodyKey::Contacts),
                    problem: BodyKeyProblem::Painleve {
                        contact,
                        mu,
                        error: e,
                    },
                }
            }
            e if contacts_given => library(BodyKey::Contacts, e),
            e @ DynamicsError::InvalidState { .. } => library(BodyKey::Omega, e),
            e @ DynamicsError::MethodTakesNoInputs { .. } => match &first_load {
                Some((key, at)) => BodyKeyError {
                    at: at.clone(),
                    problem: BodyKeyProblem::Library {
                        key: *key,
                        error: e,
                    },
                },
                None => library(BodyKey::Body, e),
            },
            e if self.pivot.is_some() => library(BodyKey::Pivot, e),
            e => library(BodyKey::Body, e),
        })?;
        Ok(id)
    }
}

#[cfg(test)]
mod tests {
    use kreisel_dynamics::{ContactLaw, ContactShape, Plan, SphereContact};

    use super::*;

    /// A unit body at rest given by its moments, every key labelled by
    /// its name (the place a client would point at).
    fn request() -> BodyRequest<&'static str> {
        BodyRequest {
            body: "body",
            mass: Some((1.0, "mass")),
            inertia: (
                BodyKey::Moments,
                Inertia::Moments(DVec3::splat(0.004)),
                "moments",
            ),
            attitude: None,
            omega_body: None,
            position: None,
            velocity: None,
            pivot: None,
            torque: None,
            torque_body: None,
            force: None,
            angular_damping: None,
            contacts: None,
        }
    }

    fn ball() -> Contacts {
        let sphere = SphereContact::try_new(0.1, DVec3::ZERO).unwrap();
        Contacts::Table(vec![TableContact {
            shape: ContactShape::Sphere(sphere),
            law: ContactLaw::new(0.3),
        }])
    }

    fn world() -> World {
        World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.01).unwrap()
    }

    fn problem(r: BodyRequest<&'static str>) -> (&'static str, BodyKeyProblem) {
        let e = r.add_to(&mut world()).unwrap_err();
        (e.at, e.problem)
    }

    #[test]
    fn each_problem_points_at_its_key() {
        let mut r = request();
        r.mass = Some((-1.0, "mass"));
        let p = BodyKeyProblem::NotPositive {
            key: BodyKey::Mass,
            value: -1.0,
        };
        assert_eq!(problem(r), ("mass", p));
        let mut r = request();
        r.mass = None;
        assert_eq!(problem(r), ("body", BodyKeyProblem::MissingMass));
        let mut r = request();
        r.attitude = Some((Attitude::Quaternion([0.0; 4]), "attitude"));
        assert_eq!(problem(r), ("attitude", BodyKeyProblem::NotAQuaternion));
        let mut r = request();
        r.pivot = Some((DVec3::Z, "pivot"));
        r.velocity = Some((DVec3::X, "velocity"));
        assert_eq!(problem(r), ("velocity", BodyKeyProblem::VelocityWithPivot));
        let mut r = request();
        r.pivot = Some((DVec3::Z, "pivot"));
        r.contacts = Some((ball(), "contacts"));
        assert_eq!(problem(r), ("pivot", BodyKeyProblem::PivotWithContacts));
        let mut r = request();
        r.contacts = Some((ball(), "contacts"));
        r.angular_damping = Some((0.5, "angular_damping"));
        let p = BodyKeyProblem::LoadsOnTable {
            key: BodyKey::AngularDamping,
        };
        assert_eq!(problem(r), ("angular_damping", p));
        let mut r = request();
        r.angular_damping = Some((-0.5, "angular_damping"));
        assert_eq!(
            problem(r),
            ("angular_damping", BodyKeyProblem::Damping { value: -0.5 })
        );
        // Moments that break the triangle inequality: the library's error,
        // at the inertia key.
        let mut r = request();
        r.inertia = (
            BodyKey::Moments,
            Inertia::Moments(DVec3::new(1.0, 1.0, 3.0)),
            "moments",
        );
        let (at, p) = problem(r);
        assert_eq!(at, "moments");
        assert!(
            matches!(
                p,
                BodyKeyProblem::Library {
                    key: BodyKey::Moments,
                    error: DynamicsError::UnphysicalInertia { .. }
                }
            ),
            "{p:?}"
        );
    }

    #[test]
    fn a_body_on_the_table_starts_touching_unless_placed() {
        let mut w = world();
        let mut r = request();
        r.contacts = Some((ball(), "contacts"));
        let id = r.clone().add_to(&mut w).unwrap();
        assert!(matches!(w.plan(id), Some(Plan::OnTable { .. })));
        // The ball's radius above the table: touching.
        assert_eq!(w.state(id).unwrap().position, DVec3::new(0.0, 0.0, 0.1));
        // Placed below it: the start is refused, at the position.
        r.position = Some((DVec3::new(0.0, 0.0, 0.05), "position"));
        let (at, p) = problem(r);
        assert_eq!(at, "position");
        assert!(
            matches!(
                p,
                BodyKeyProblem::InsideTable {
                    contact: 0,
                    position_given: true,
                    ..
                }
            ),
            "{p:?}"
        );
    }
}
