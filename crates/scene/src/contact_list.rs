//! A body's contacts as a list, each checked by its [`ContactRequest`]:
//! on the ground (the first touching, up to
//! [`kreisel_dynamics::MAX_OTHER_CONTACTS`] more
//! watched for touchdown) or, when one of them has friction "coulomb", on
//! the table (every one a contact with its law, up to
//! [`kreisel_dynamics::TableBody::MAX_CONTACTS`]) — the scene file's
//! `[[body.contact]]` tables ([`contacts`]); Python's bodies with contacts
//! are all on the table ([`on_table`]).

use kreisel_dynamics::{ContactShape, TableContact};

use crate::contact_key::{ContactKeyError, ContactKeyProblem, FrictionName, Surface};
use crate::contact_request::{CheckedContact, ContactRequest};

/// A body's checked contacts: the one it stands on, and the further
/// shapes watched for touchdown (the contacts after the first).
#[derive(Debug, Clone)]
pub struct CheckedContacts {
    /// The first contact: the surface touching the plane and its friction.
    pub first: CheckedContact,
    /// The shapes of the other contacts, in order.
    pub others: Vec<ContactShape>,
}

/// A body's checked contacts: on the ground (one touching, others
/// watched) or on the table (every one a contact with its law).
#[derive(Debug, Clone)]
pub enum Contacts {
    /// Regularised or rolling friction at the first contact.
    Ground(CheckedContacts),
    /// `friction = "coulomb"`: every contact, in order.
    Table(Vec<TableContact>),
}

/// A body's contacts (given at `list`): on the table when one of them has
/// friction "coulomb" — then every one, up to [`Surface::Table`]'s most —
/// else on the ground, the first touching and the others watched for
/// touchdown, up to [`Surface::Ground`]'s most.
///
/// # Errors
/// The first problem found, at the key it is about.
///
/// ```
/// use kreisel_scene::contact_key::{ContactKey, ContactKeyProblem, FrictionName, Needs};
/// use kreisel_scene::contact_list::{Contacts, contacts};
/// use kreisel_scene::contact_request::ContactRequest;
/// let mut ball = ContactRequest::new("ball");
/// ball.shape = Some(("sphere".to_owned(), "shape"));
/// ball.radius = Some((0.1, "radius"));
/// ball.friction = Some(("coulomb".to_owned(), "friction"));
/// let e = contacts(&[ball.clone()], "contacts").unwrap_err();
/// let needs = Needs::Coefficient { friction: FrictionName::Coulomb };
/// assert_eq!((e.at, e.contact), ("friction", Some(0)));
/// assert_eq!(e.problem, ContactKeyProblem::Missing { key: ContactKey::Mu, needs });
/// ball.mu = Some((0.3, "mu"));
/// let Ok(Contacts::Table(table)) = contacts(&[ball], "contacts") else { panic!() };
/// assert_eq!(table[0].law.mu(), 0.3);
/// ```
pub fn contacts<A: Clone>(
    requests: &[ContactRequest<A>],
    list: A,
) -> Result<Contacts, ContactKeyError<A>> {
    let Some((first, others)) = requests.split_first() else {
        return Err(no_contacts(list));
    };
    let coulomb = requests.iter().position(|r| {
        r.friction
            .as_ref()
            .is_some_and(|(f, _)| f == FrictionName::COULOMB)
    });
    match coulomb {
        Some(c) => table(requests, Some(c)).map(Contacts::Table),
        None => ground(first, others).map(Contacts::Ground),
    }
}

/// The contacts (given at `list`) of a body that is on the table whatever
/// they say: friction "coulomb" at each (the default), at least one, up
/// to [`Surface::Table`]'s most.
///
/// # Errors
/// As [`contacts`].
///
/// ```
/// use kreisel_scene::contact_key::{ContactKeyProblem, Surface};
/// use kreisel_scene::contact_list::on_table;
/// use kreisel_scene::contact_request::ContactRequest;
/// let mut ball = ContactRequest::new(());
/// ball.shape = Some(("sphere".to_owned(), ()));
/// ball.radius = Some((0.1, ()));
/// ball.mu = Some((0.3, ()));
/// assert_eq!(on_table(&[ball.clone()], ())?.len(), 1);
/// let e = on_table(&vec![ball; 9], ()).unwrap_err();
/// assert_eq!(e.problem, ContactKeyProblem::TooMany { given: 9, surface: Surface::Table });
/// assert_eq!(on_table::<()>(&[], ()).unwrap_err().problem, ContactKeyProblem::NoContacts);
/// # Ok::<(), kreisel_scene::contact_key::ContactKeyError<()>>(())
/// ```
pub fn on_table<A: Clone>(
    requests: &[ContactRequest<A>],
    list: A,
) -> Result<Vec<TableContact>, ContactKeyError<A>> {
    if requests.is_empty() {
        return Err(no_contacts(list));
    }
    table(requests, None)
}

/// The problem of no contact in the list given at `list`.
fn no_contacts<A>(list: A) -> ContactKeyError<A> {
    ContactKeyError {
        at: list,
        contact: None,
        problem: ContactKeyProblem::NoContacts,
    }
}

/// `given` contacts on `surface`, of which `extra` is the first beyond
/// its most: a problem there.
fn too_many<A: Clone>(
    given: usize,
    extra: Option<&ContactRequest<A>>,
    surface: Surface,
) -> Result<(), ContactKeyError<A>> {
    match extra {
        Some(extra) => Err(ContactKeyError {
            at: extra.contact.clone(),
            contact: Some(surface.most()),
            problem: ContactKeyProblem::TooMany { given, surface },
        }),
        None => Ok(()),
    }
}

/// The contacts of a body on the table (`coulomb`: the contact whose
/// friction "coulomb" puts it there; none: "coulomb" where not given).
fn table<A: Clone>(
    requests: &[ContactRequest<A>],
    coulomb: Option<usize>,
) -> Result<Vec<TableContact>, ContactKeyError<A>> {
    let surface = Surface::Table;
    too_many(requests.len(), requests.get(surface.most()), surface)?;
    requests
        .iter()
        .enumerate()
        .map(|(n, request)| request.table_contact(n, coulomb))
        .collect()
}

/// The contacts of a body on the ground: the first touching, the others
/// watched for touchdown.
fn ground<A: Clone>(
    first: &ContactRequest<A>,
    others: &[ContactRequest<A>],
) -> Result<CheckedContacts, ContactKeyError<A>> {
    let surface = Surface::Ground;
    too_many(1 + others.len(), others.get(surface.most() - 1), surface)?;
    let first = first.touching(0)?;
    let others = others
        .iter()
        .enumerate()
        .map(|(n, other)| other.watched(n + 1))
        .collect::<Result<_, _>>()?;
    Ok(CheckedContacts { first, others })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact_key::{ContactKey, NotFor};

    /// A contact of `shape` (radius 0.1 m) with `friction`, each key
    /// labelled by its name and the contact's number.
    fn contact(n: usize, friction: Option<&str>) -> ContactRequest<String> {
        let at = |key: &str| format!("{n}.{key}");
        let mut c = ContactRequest::new(at("contact"));
        c.shape = Some(("sphere".to_owned(), at("shape")));
        c.radius = Some((0.1, at("radius")));
        c.center = Some((glam::DVec3::new(0.0, 0.0, n as f64), at("center")));
        c.friction = friction.map(|f| (f.to_owned(), at("friction")));
        c.mu = friction
            .filter(|f| matches!(*f, "sliding" | "viscous" | "coulomb"))
            .map(|_| (0.3, at("mu")));
        c
    }

    fn problem(requests: &[ContactRequest<String>]) -> (String, Option<usize>, ContactKeyProblem) {
        let e = contacts(requests, "list".to_owned()).unwrap_err();
        (e.at, e.contact, e.problem)
    }

    #[test]
    fn the_list_is_on_the_ground_unless_one_contact_is_coulomb() {
        let ground = [contact(0, Some("sliding")), contact(1, None)];
        let Ok(Contacts::Ground(checked)) = contacts(&ground, String::new()) else {
            panic!("not on the ground");
        };
        assert_eq!(checked.others.len(), 1);
        let table = [contact(0, Some("coulomb")), contact(1, Some("coulomb"))];
        let Ok(Contacts::Table(checked)) = contacts(&table, String::new()) else {
            panic!("not on the table");
        };
        assert_eq!(checked.len(), 2);
    }

    #[test]
    fn each_list_problem_points_at_its_contact() {
        assert_eq!(
            problem(&[]),
            ("list".into(), None, ContactKeyProblem::NoContacts)
        );
        // Six on the ground: the sixth is one too many.
        let six: Vec<_> = (0..6)
            .map(|n| contact(n, (n == 0).then_some("none")))
            .collect();
        let too_many = ContactKeyProblem::TooMany {
            given: 6,
            surface: Surface::Ground,
        };
        assert_eq!(problem(&six), ("5.contact".into(), Some(5), too_many));
        // Nine on the table: the ninth.
        let nine: Vec<_> = (0..9).map(|n| contact(n, Some("coulomb"))).collect();
        let too_many = ContactKeyProblem::TooMany {
            given: 9,
            surface: Surface::Table,
        };
        assert_eq!(problem(&nine), ("8.contact".into(), Some(8), too_many));
        // "coulomb" on the second makes the first's "sliding" the error.
        let mixed = [contact(0, Some("sliding")), contact(1, Some("coulomb"))];
        let not_coulomb = ContactKeyProblem::NotCoulomb {
            friction: "sliding".into(),
            coulomb: Some(1),
        };
        assert_eq!(problem(&mixed), ("0.friction".into(), Some(0), not_coulomb));
        // A watched contact with a coefficient.
        let mut watched = contact(1, None);
        watched.mu = Some((0.3, "1.mu".into()));
        let not_for = ContactKeyProblem::NotFor {
            key: ContactKey::Mu,
            why: NotFor::Watched,
        };
        let list = [contact(0, Some("rolling")), watched];
        assert_eq!(problem(&list), ("1.mu".into(), Some(1), not_for));
    }
}
