//! A contact as its user gives it, key by key, checked in one place into
//! the library's [`ContactShape`], [`Friction`] and [`ContactLaw`]: the
//! scene file's `[[body.contact]]` tables (`contact_keys.rs`) and Python's
//! `World.add_body(contacts=[…])` both fill in a [`ContactRequest`] per
//! contact; the list's rules (on the ground or on the table, how many)
//! are `contact_list.rs`'s.
//!
//! Each value comes with where it was given (`A`: a span of the scene's
//! text, nothing for a Python dict); a problem is a typed
//! [`ContactKeyProblem`] at the place of the key it is about, which the
//! client words in its own names.
//!
//! ```text
//! shape     sphere: radius · disk: radius, normal · ellipsoid: semi_axes (contact_shape.rs)
//! touching  friction none · viscous, sliding: mu ≥ 0 (sliding: slip_velocity > 0) · rolling
//! watched   a shape only: no key of a law
//! table     friction "coulomb": mu, restitution, tangential_restitution, contensou_radius,
//!           rolling_resistance (the law's own checks); air_viscosity, air_gap (a disk only)
//! ```

use glam::DVec3;
use kreisel_dynamics::{
    AirLayer, ContactLaw, ContactShape, DynamicsError, Friction, FrictionModel, TableContact,
};

use crate::body_key::Given;
use crate::contact_key::{
    ContactKey, ContactKeyError, ContactKeyProblem, FrictionName, Needs, NotFor, ShapeName,
};

/// A checked contact: the shape and the friction.
#[derive(Debug, Clone, Copy)]
pub struct CheckedContact {
    /// The touching surface.
    pub shape: ContactShape,
    /// The friction law at the contact.
    pub friction: Friction,
}

/// The air layer's floor `h₀` when `air_gap` is not given, m.
pub const DEFAULT_AIR_GAP: f64 = 1e-6;

/// Everything a user gives of one contact.
#[derive(Debug, Clone)]
pub struct ContactRequest<A> {
    /// Where the contact is given as a whole.
    pub contact: A,
    /// The shape's name ([`ShapeName`]).
    pub shape: Given<String, A>,
    /// A sphere's or a disk's radius, m.
    pub radius: Given<f64, A>,
    /// The shape's centre from the centre of mass, body axes, m (zero without).
    pub center: Given<DVec3, A>,
    /// A disk's axis, body axes.
    pub normal: Given<DVec3, A>,
    /// An ellipsoid's semi-axes, m.
    pub semi_axes: Given<DVec3, A>,
    /// The friction law's name ([`FrictionName`]).
    pub friction: Given<String, A>,
    /// The friction coefficient.
    pub mu: Given<f64, A>,
    /// Friction "sliding"'s ε, m/s ([`Friction::DEFAULT_SLIP_VELOCITY`] without).
    pub slip_velocity: Given<f64, A>,
    /// Newton's restitution (0 without).
    pub restitution: Given<f64, A>,
    /// Garwin's tangential restitution (0 without).
    pub tangential_restitution: Given<f64, A>,
    /// Contensou's radius, m (0 without).
    pub contensou_radius: Given<f64, A>,
    /// The rolling resistance, m (0 without).
    pub rolling_resistance: Given<f64, A>,
    /// The air layer's viscosity, Pa s (no air layer without).
    pub air_viscosity: Given<f64, A>,
    /// The air layer's floor, m ([`DEFAULT_AIR_GAP`] without).
    pub air_gap: Given<f64, A>,
}

/// A problem of one contact, at its place (the list adds which contact).
pub(crate) type Fault<A> = (A, ContactKeyProblem);

/// `key` given where it has no meaning (`why`): a problem at its place.
pub(crate) fn not_given<T, A: Clone>(
    given: &Given<T, A>,
    key: ContactKey,
    why: NotFor,
) -> Result<(), Fault<A>> {
    match given {
        Some((_, at)) => Err((at.clone(), ContactKeyProblem::NotFor { key, why })),
        None => Ok(()),
    }
}

/// A key that is needed (`needs`), or a problem at `at`.
pub(crate) fn needed<'g, T, A: Clone>(
    given: &'g Given<T, A>,
    key: ContactKey,
    needs: Needs,
    at: &A,
) -> Result<&'g (T, A), Fault<A>> {
    given
        .as_ref()
        .ok_or_else(|| (at.clone(), ContactKeyProblem::Missing { key, needs }))
}

impl<A: Clone> ContactRequest<A> {
    /// A contact given at `contact` with no keys yet.
    pub fn new(contact: A) -> Self {
        Self {
            contact,
            shape: None,
            radius: None,
            center: None,
            normal: None,
            semi_axes: None,
            friction: None,
            mu: None,
            slip_velocity: None,
            restitution: None,
            tangential_restitution: None,
            contensou_radius: None,
            rolling_resistance: None,
            air_viscosity: None,
            air_gap: None,
        }
    }

    /// The value of the number `key` (`radius`, `mu`, …; none for the
    /// shape's and the friction's names and the vectors), to be filled in
    /// by a client that reads keys by name.
    ///
    /// ```
    /// use kreisel_scene::contact_key::ContactKey;
    /// use kreisel_scene::contact_request::ContactRequest;
    /// let mut c = ContactRequest::new(());
    /// *c.number_mut(ContactKey::AirGap).unwrap() = Some((1e-6, ()));
    /// assert_eq!(c.air_gap, Some((1e-6, ())));
    /// assert!(c.number_mut(ContactKey::Normal).is_none());
    /// ```
    pub fn number_mut(&mut self, key: ContactKey) -> Option<&mut Given<f64, A>> {
        match key {
            ContactKey::Radius => Some(&mut self.radius),
            ContactKey::Mu => Some(&mut self.mu),
            ContactKey::SlipVelocity => Some(&mut self.slip_velocity),
            ContactKey::Restitution => Some(&mut self.restitution),
            ContactKey::TangentialRestitution => Some(&mut self.tangential_restitution),
            ContactKey::ContensouRadius => Some(&mut self.contensou_radius),
            ContactKey::RollingResistance => Some(&mut self.rolling_resistance),
            ContactKey::AirViscosity => Some(&mut self.air_viscosity),
            ContactKey::AirGap => Some(&mut self.air_gap),
            ContactKey::Shape
            | ContactKey::Center
            | ContactKey::Normal
            | ContactKey::SemiAxes
            | ContactKey::Friction => None,
        }
    }

    /// The contact a body on the ground stands on (number `index`,
    /// 0-based, in the errors): its shape and friction model.
    ///
    /// # Errors
    /// The first problem, at the key it is about.
    pub fn touching(&self, index: usize) -> Result<CheckedContact, ContactKeyError<A>> {
        let (_, shape) = self.shape().map_err(of(index))?;
        let friction = self.ground_friction().map_err(of(index))?;
        Ok(CheckedContact { shape, friction })
    }

    /// A further contact of a body on the ground (number `index`),
    /// watched for touchdown: its shape, and no law.
    ///
    /// # Errors
    /// The first problem, at the key it is about: a key of a law is one.
    pub fn watched(&self, index: usize) -> Result<ContactShape, ContactKeyError<A>> {
        let (_, shape) = self.shape().map_err(of(index))?;
        not_given(&self.friction, ContactKey::Friction, NotFor::Watched).map_err(of(index))?;
        let law = [
            (ContactKey::Mu, &self.mu),
            (ContactKey::SlipVelocity, &self.slip_velocity),
        ];
        for (key, given) in law.into_iter().chain(self.coulomb_keys()) {
            not_given(given, key, NotFor::Watched).map_err(of(index))?;
        }
        Ok(shape)
    }

    /// A contact of a body on the table (number `index`): its shape and
    /// Coulomb law. `coulomb`: the contact whose friction "coulomb" puts
    /// the body there, and every contact must say so; none: the friction
    /// is "coulomb" where not given.
    ///
    /// # Errors
    /// The first problem, at the key it is about.
    ///
    /// ```
    /// use kreisel_scene::contact_key::{ContactKey, ContactKeyProblem, FrictionName, Needs};
    /// use kreisel_scene::contact_request::ContactRequest;
    /// let mut ball = ContactRequest::new("ball");
    /// ball.shape = Some(("sphere".to_owned(), "shape"));
    /// ball.radius = Some((0.1, "radius"));
    /// let e = ball.table_contact(2, Some(0)).unwrap_err();
    /// let needs = Needs::TableLaw { coulomb: 0 };
    /// assert_eq!((e.at, e.contact), ("shape", Some(2)));
    /// assert_eq!(e.problem, ContactKeyProblem::Missing { key: ContactKey::Friction, needs });
    /// let e = ball.table_contact(2, None).unwrap_err();
    /// let needs = Needs::Coefficient { friction: FrictionName::Coulomb };
    /// assert_eq!(e.problem, ContactKeyProblem::Missing { key: ContactKey::Mu, needs });
    /// ball.mu = Some((0.3, "mu"));
    /// assert_eq!(ball.table_contact(2, None)?.law.mu(), 0.3);
    /// # Ok::<(), kreisel_scene::contact_key::ContactKeyError<&str>>(())
    /// ```
    pub fn table_contact(
        &self,
        index: usize,
        coulomb: Option<usize>,
    ) -> Result<TableContact, ContactKeyError<A>> {
        let (name, shape) = self.shape().map_err(of(index))?;
        let at = match (&self.friction, coulomb) {
            (None, Some(coulomb)) => {
                let problem = ContactKeyProblem::Missing {
                    key: ContactKey::Friction,
                    needs: Needs::TableLaw { coulomb },
                };
                return Err(of(index)((self.shape_at().clone(), problem)));
            }
            (None, None) => &self.contact,
            (Some((friction, at)), _) if friction != FrictionName::COULOMB => {
                let friction = friction.clone();
                let problem = ContactKeyProblem::NotCoulomb { friction, coulomb };
                return Err(of(index)((at.clone(), problem)));
            }
            (Some((_, at)), _) => at,
        };
        let law = self.law(name, at).map_err(of(index))?;
        Ok(TableContact { shape, law })
    }

    /// The keys of friction "coulomb", in the order they are checked.
    fn coulomb_keys(&self) -> [(ContactKey, &Given<f64, A>); 6] {
        [
            (ContactKey::Restitution, &self.restitution),
            (
                ContactKey::TangentialRestitution,
                &self.tangential_restitution,
            ),
            (ContactKey::ContensouRadius, &self.contensou_radius),
            (ContactKey::RollingResistance, &self.rolling_resistance),
            (ContactKey::AirViscosity, &self.air_viscosity),
            (ContactKey::AirGap, &self.air_gap),
        ]
    }

    /// The friction law of the contact a body on the ground stands on,
    /// from `friction`, `mu` and `slip_velocity`.
    fn ground_friction(&self) -> Result<Friction, Fault<A>> {
        let (name, at) = needed(
            &self.friction,
            ContactKey::Friction,
            Needs::Standing,
            self.shape_at(),
        )?;
        let model: FrictionModel = name.parse().map_err(|_| {
            let name = name.clone();
            (at.clone(), ContactKeyProblem::UnknownFriction { name })
        })?;
        for (key, given) in self.coulomb_keys() {
            not_given(given, key, NotFor::OnlyCoulomb)?;
        }
        let friction = FrictionName::Ground(model);
        if model != FrictionModel::Sliding {
            let why = NotFor::OnlySliding { friction };
            not_given(&self.slip_velocity, ContactKey::SlipVelocity, why)?;
        }
        let mu = || -> Result<f64, Fault<A>> {
            let needs = Needs::Coefficient { friction };
            let (mu, mu_at) = needed(&self.mu, ContactKey::Mu, needs, at)?;
            if mu.is_finite() && *mu >= 0.0 {
                Ok(*mu)
            } else {
                let problem = ContactKeyProblem::Negative {
                    key: ContactKey::Mu,
                    value: *mu,
                };
                Err((mu_at.clone(), problem))
            }
        };
        let no_mu = || not_given(&self.mu, ContactKey::Mu, NotFor::NoCoefficient { friction });
        match model {
            FrictionModel::None => no_mu().map(|()| Friction::None),
            FrictionModel::Rolling => no_mu().map(|()| Friction::Rolling),
            FrictionModel::Viscous => Ok(Friction::Viscous { mu: mu()? }),
            FrictionModel::Sliding => {
                let mu = mu()?;
                let slip_velocity = match &self.slip_velocity {
                    Some((v, at)) => positive(*v, ContactKey::SlipVelocity, at)?,
                    None => Friction::DEFAULT_SLIP_VELOCITY,
                };
                Ok(Friction::Sliding { mu, slip_velocity })
            }
        }
    }

    /// The Coulomb law of a contact of `shape` on the table from `mu`,
    /// `restitution`, `tangential_restitution`, `contensou_radius`,
    /// `rolling_resistance`, `air_viscosity` and `air_gap` (`at`: where
    /// its friction is, else the contact).
    fn law(&self, shape: ShapeName, at: &A) -> Result<ContactLaw, Fault<A>> {
        let why = NotFor::OnlySliding {
            friction: FrictionName::Coulomb,
        };
        not_given(&self.slip_velocity, ContactKey::SlipVelocity, why)?;
        let needs = Needs::Coefficient {
            friction: FrictionName::Coulomb,
        };
        let (mu, mu_at) = needed(&self.mu, ContactKey::Mu, needs, at)?;
        // Each key's value, checked by the law itself; its error at the key.
        let mut law = ContactLaw::try_new(*mu).map_err(refused(ContactKey::Mu, mu_at))?;
        type Setter = fn(ContactLaw, f64) -> Result<ContactLaw, DynamicsError>;
        let setters: [Setter; 4] = [
            ContactLaw::try_with_restitution,
            ContactLaw::try_with_tangential_restitution,
            ContactLaw::try_with_contensou_radius,
            ContactLaw::try_with_rolling_resistance,
        ];
        // (the first four keys of "coulomb"; the air layer's two below)
        for ((key, given), set) in self.coulomb_keys().into_iter().zip(setters) {
            if let Some((value, at)) = given {
                law = set(law, *value).map_err(refused(key, at))?;
            }
        }
        let Some((viscosity, viscosity_at)) = &self.air_viscosity else {
            not_given(&self.air_gap, ContactKey::AirGap, NotFor::NoAirViscosity)?;
            return Ok(law);
        };
        if shape != ShapeName::Disk {
            let problem = ContactKeyProblem::NotFor {
                key: ContactKey::AirViscosity,
                why: NotFor::AirOnlyDisk,
            };
            return Err((viscosity_at.clone(), problem));
        }
        let floor = self.air_gap.as_ref().map_or(DEFAULT_AIR_GAP, |(g, _)| *g);
        let layer = AirLayer::try_new(*viscosity, floor);
        let (key, at) = match (&layer, &self.air_gap) {
            (
                Err(DynamicsError::InvalidContact {
                    parameter: "air_gap",
                    ..
                }),
                Some((_, gap_at)),
            ) => (ContactKey::AirGap, gap_at),
            _ => (ContactKey::AirViscosity, viscosity_at),
        };
        layer
            .map(|l| law.with_air_layer(l))
            .map_err(refused(key, at))
    }
}

/// `value` when every component is finite, else a problem at `at`.
pub(crate) fn finite<A: Clone>(value: DVec3, key: ContactKey, at: &A) -> Result<DVec3, Fault<A>> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err((at.clone(), ContactKeyProblem::NotFinite { key }))
    }
}

/// `value` when positive and finite, else a problem at `at`.
pub(crate) fn positive<A: Clone>(value: f64, key: ContactKey, at: &A) -> Result<f64, Fault<A>> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err((at.clone(), ContactKeyProblem::NotPositive { key, value }))
    }
}

/// `fault` of contact `index`.
fn of<A>(index: usize) -> impl Fn(Fault<A>) -> ContactKeyError<A> {
    move |(at, problem)| ContactKeyError {
        at,
        contact: Some(index),
        problem,
    }
}

/// The library's refusal of the value of `key` given at `at`.
pub(crate) fn refused<A: Clone>(
    key: ContactKey,
    at: &A,
) -> impl Fn(DynamicsError) -> Fault<A> + '_ {
    move |error| (at.clone(), ContactKeyProblem::Library { key, error })
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use ContactKey as K;
    use ContactKeyProblem as P;

    /// A good contact of `shape` with `friction`, every key labelled by
    /// its name (the place a client would point at).
    pub(crate) fn request(shape: &str, friction: &str) -> ContactRequest<&'static str> {
        let mut r = ContactRequest::new("contact");
        r.shape = Some((shape.to_owned(), "shape"));
        r.friction = Some((friction.to_owned(), "friction"));
        match shape {
            "disk" => {
                r.radius = Some((0.1, "radius"));
                r.normal = Some((DVec3::Z, "normal"));
            }
            "ellipsoid" => r.semi_axes = Some((DVec3::new(0.2, 0.03, 0.02), "semi_axes")),
            _ => r.radius = Some((0.1, "radius")),
        }
        if !matches!(friction, "none" | "rolling") {
            r.mu = Some((0.3, "mu"));
        }
        r
    }

    /// Where `r`'s problem is and what it is: as the contact a body on the
    /// ground stands on, or (`table`) one of a body on the table.
    fn problem(r: &ContactRequest<&'static str>, table: bool) -> (&'static str, ContactKeyProblem) {
        let e = match table {
            true => r.table_contact(0, Some(0)).map(|_| ()).unwrap_err(),
            false => r.touching(0).map(|_| ()).unwrap_err(),
        };
        assert_eq!(e.contact, Some(0));
        (e.at, e.problem)
    }

    /// A change to a good request.
    pub(crate) type Change = fn(&mut ContactRequest<&'static str>);

    #[test]
    fn each_problem_points_at_its_key() {
        let not_for = |key, why| P::NotFor { key, why };
        let missing = |key, needs| P::Missing { key, needs };
        let ground = |model| FrictionName::Ground(model);
        #[rustfmt::skip] // one case a line
        let cases: Vec<(&str, &str, Change, &str, ContactKeyProblem)> = vec![
            ("sphere", "none", |r| r.friction = None, "shape", missing(K::Friction, Needs::Standing)),
            ("sphere", "slidng", |_| {}, "friction", P::UnknownFriction { name: "slidng".into() }),
            ("sphere", "sliding", |r| r.restitution = Some((0.5, "restitution")), "restitution", not_for(K::Restitution, NotFor::OnlyCoulomb)),
            ("sphere", "rolling", |r| r.mu = Some((0.3, "mu")), "mu", not_for(K::Mu, NotFor::NoCoefficient { friction: ground(FrictionModel::Rolling) })),
            ("sphere", "none", |r| r.slip_velocity = Some((1e-3, "slip_velocity")), "slip_velocity", not_for(K::SlipVelocity, NotFor::OnlySliding { friction: ground(FrictionModel::None) })),
            ("sphere", "viscous", |r| r.mu = None, "friction", missing(K::Mu, Needs::Coefficient { friction: ground(FrictionModel::Viscous) })),
            ("sphere", "sliding", |r| r.mu = Some((-1.0, "mu")), "mu", P::Negative { key: K::Mu, value: -1.0 }),
            ("sphere", "sliding", |r| r.slip_velocity = Some((0.0, "slip_velocity")), "slip_velocity", P::NotPositive { key: K::SlipVelocity, value: 0.0 }),
            ("sphere", "coulomb", |r| r.slip_velocity = Some((1e-3, "slip_velocity")), "slip_velocity", not_for(K::SlipVelocity, NotFor::OnlySliding { friction: FrictionName::Coulomb })),
            ("sphere", "coulomb", |r| r.mu = None, "friction", missing(K::Mu, Needs::Coefficient { friction: FrictionName::Coulomb })),
            ("sphere", "coulomb", |r| r.friction = None, "shape", missing(K::Friction, Needs::TableLaw { coulomb: 0 })),
            ("sphere", "coulomb", |r| r.air_viscosity = Some((1e-5, "air_viscosity")), "air_viscosity", not_for(K::AirViscosity, NotFor::AirOnlyDisk)),
            ("disk", "coulomb", |r| r.air_gap = Some((1e-6, "air_gap")), "air_gap", not_for(K::AirGap, NotFor::NoAirViscosity)),
        ];
        for (shape, friction, change, at, expected) in cases {
            let mut r = request(shape, friction);
            change(&mut r);
            let table = friction == FrictionName::COULOMB;
            assert_eq!(problem(&r, table), (at, expected), "{shape}, {friction}");
        }
    }

    #[test]
    fn the_library_refuses_values_at_their_keys() {
        #[rustfmt::skip] // one case a line
        let cases: [(&str, Change, &str, ContactKey); 4] = [
            ("sphere", |r| r.mu = Some((-0.1, "mu")), "mu", K::Mu),
            ("sphere", |r| r.tangential_restitution = Some((1.5, "tangential_restitution")), "tangential_restitution", K::TangentialRestitution),
            ("disk", |r| { r.air_viscosity = Some((1e-5, "air_viscosity")); r.air_gap = Some((0.0, "air_gap")) }, "air_gap", K::AirGap),
            ("disk", |r| { r.air_viscosity = Some((-1.0, "air_viscosity")); r.air_gap = Some((0.0, "air_gap")) }, "air_viscosity", K::AirViscosity),
        ];
        for (shape, change, at, key) in cases {
            let mut r = request(shape, "coulomb");
            change(&mut r);
            let (found, p) = problem(&r, true);
            assert!(
                found == at && matches!(p, P::Library { key: k, .. } if k == key),
                "{found}: {p:?}"
            );
        }
    }

    #[test]
    fn good_keys_make_the_library_s_contacts() {
        let sliding = request("sphere", "sliding").touching(0).unwrap().friction;
        let slip_velocity = Friction::DEFAULT_SLIP_VELOCITY;
        assert_eq!(
            sliding,
            Friction::Sliding {
                mu: 0.3,
                slip_velocity
            }
        );
        let mut disk = request("disk", "coulomb");
        disk.air_viscosity = Some((1.8e-5, "air_viscosity"));
        let law = disk.table_contact(0, None).unwrap().law;
        assert_eq!(
            law.air_layer(),
            AirLayer::try_new(1.8e-5, DEFAULT_AIR_GAP).ok()
        );
        // Watched: a shape, and no key of a law.
        let mut stem = request("sphere", "none");
        stem.friction = None;
        assert!(stem.watched(1).is_ok());
        stem.contensou_radius = Some((1e-3, "contensou_radius"));
        let e = stem.watched(1).unwrap_err();
        let p = P::NotFor {
            key: K::ContensouRadius,
            why: NotFor::Watched,
        };
        assert_eq!(
            (e.at, e.contact, e.problem),
            ("contensou_radius", Some(1), p)
        );
    }
}
