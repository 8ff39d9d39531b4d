//! The CSV that `kreisel simulate` writes: a header, then one row per body
//! and output time, streamed; the columns are today's thirteen unless
//! `--columns` chooses others ([`Column`]).

#![forbid(unsafe_code)]

use std::io::{self, Write};

use kreisel_dynamics::{BodyId, BodyState, World};

use crate::numbers::{Shortest, write_numbers};

/// The header line, without its newline.
pub const HEADER: &str = "t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz";

/// One CSV column: its name is its header field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Column {
    /// `t`: time, s.
    T,
    /// `body`: the body's name.
    Body,
    /// `qw`, `qx`, `qy`, `qz`: attitude component 0..4 (w, x, y, z).
    Q(usize),
    /// `wx`, `wy`, `wz`: angular velocity, body axes.
    Omega(usize),
    /// `energy`, J.
    Energy,
    /// `lx`, `ly`, `lz`: angular momentum, world axes.
    L(usize),
    /// `x`, `y`, `z`: centre of mass, world axes, m.
    X(usize),
    /// `vx`, `vy`, `vz`: its velocity, world axes, m/s.
    V(usize),
}

impl Column {
    /// Every column, in the order of [`Column::names`].
    pub const ALL: [Column; 19] = [
        Column::T,
        Column::Body,
        Column::Q(0),
        Column::Q(1),
        Column::Q(2),
        Column::Q(3),
        Column::Omega(0),
        Column::Omega(1),
        Column::Omega(2),
        Column::Energy,
        Column::L(0),
        Column::L(1),
        Column::L(2),
        Column::X(0),
        Column::X(1),
        Column::X(2),
        Column::V(0),
        Column::V(1),
        Column::V(2),
    ];

    /// The default columns: the first thirteen ([`HEADER`]).
    pub fn default_columns() -> Vec<Column> {
        Column::ALL[..13].to_vec()
    }

    /// The header field.
    pub fn name(self) -> &'static str {
        const XYZ: [&str; 3] = ["x", "y", "z"];
        const W: [&str; 3] = ["wx", "wy", "wz"];
        const L: [&str; 3] = ["lx", "ly", "lz"];
        const V: [&str; 3] = ["vx", "vy", "vz"];
        const Q: [&str; 4] = ["qw", "qx", "qy", "qz"];
        match self {
            Column::T => "t",
            Column::Body => "body",
            Column::Q(i) => Q[i],
            Column::Omega(i) => W[i],
            Column::Energy => "energy",
            Column::L(i) => L[i],
            Column::X(i) => XYZ[i],
            Column::V(i) => V[i],
        }
    }

    /// The number this column holds for `state`; `None` for `body` (the
    /// body's name, which the state does not know).
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::BodyState;
    /// use kreisel_scene::columns::Column;
    /// let s = BodyState {
    ///     time: 0.5,
    ///     world_from_body: DQuat::IDENTITY,
    ///     omega_body: DVec3::new(1.0, 2.0, 3.0),
    ///     l_world: DVec3::ZERO,
    ///     energy: 7.0,
    ///     position: DVec3::new(0.0, 0.0, -1.0),
    ///     velocity: DVec3::ZERO,
    /// };
    /// assert_eq!(Column::T.value(&s), Some(0.5));
    /// assert_eq!(Column::Omega(1).value(&s), Some(2.0));
    /// assert_eq!(Column::X(2).value(&s), Some(-1.0));
    /// assert_eq!(Column::Body.value(&s), None);
    /// ```
    pub fn value(self, state: &BodyState) -> Option<f64> {
        let q = state.world_from_body;
        Some(match self {
            Column::T => state.time,
            Column::Body => return None,
            Column::Q(i) => [q.w, q.x, q.y, q.z][i],
            Column::Omega(i) => state.omega_body[i],
            Column::Energy => state.energy,
            Column::L(i) => state.l_world[i],
            Column::X(i) => state.position[i],
            Column::V(i) => state.velocity[i],
        })
    }

    /// Every column name, comma-separated.
    pub fn names() -> String {
        Column::ALL.map(Column::name).join(",")
    }

    /// The columns of `--columns LIST` (comma-separated names, in the order
    /// written).
    ///
    /// # Errors
    /// One line naming the first unknown or repeated name (or an empty
    /// list) and the valid names.
    pub fn parse_list(list: &str) -> Result<Vec<Column>, String> {
        let mut columns: Vec<Column> = Vec::new();
        for name in list.split(',').map(str::trim) {
            let Some(column) = Column::ALL.into_iter().find(|c| c.name() == name) else {
                return Err(format!(
                    "unknown column `{name}` (valid: {})",
                    Column::names()
                ));
            };
            if columns.contains(&column) {
                return Err(format!("column `{name}` is given twice"));
            }
            columns.push(column);
        }
        Ok(columns)
    }
}

/// The bodies' states at one time: each body's index in scene order (in
/// the scene's [`crate::run::Names`]) and its state.
pub type States = [(usize, BodyState)];

/// The state of each of `bodies` at the world's current time, in scene
/// order, into `states` (emptied first): read once per row, then checked
/// and written.
pub fn read_states(
    world: &World,
    bodies: &[(String, BodyId)],
    states: &mut Vec<(usize, BodyState)>,
) {
    states.clear();
    // Every id comes from this world, so every body has a state.
    states.extend(
        bodies
            .iter()
            .enumerate()
            .filter_map(|(index, (_, id))| Some((index, world.state(*id)?))),
    );
}

/// The first of `states` (index in scene order, its time and the column)
/// whose row would hold a number that is not finite, in any column
/// (whichever `--columns` writes).
pub fn first_non_finite(states: &States) -> Option<(usize, f64, &'static str)> {
    states.iter().find_map(|(index, s)| {
        // `t` comes first in `ALL`: a time that is not finite is named so.
        Column::ALL
            .into_iter()
            .find(|c| c.value(s).is_some_and(|x| !x.is_finite()))
            .map(|column| (*index, s.time, column.name()))
    })
}

/// Writes the header and the rows to `out` (which should be buffered).
#[derive(Debug)]
pub struct CsvWriter<W: Write> {
    out: W,
    /// `None`: the default columns, written by the fast path.
    columns: Option<Vec<Column>>,
}

impl<W: Write> CsvWriter<W> {
    /// Writes the header line of `columns` (in this order).
    ///
    /// # Errors
    /// The writer's errors.
    pub fn with_columns(mut out: W, columns: Vec<Column>) -> io::Result<Self> {
        if columns == Column::default_columns() {
            writeln!(out, "{HEADER}")?;
            return Ok(Self { out, columns: None });
        }
        let names: Vec<&str> = columns.iter().map(|c| c.name()).collect();
        writeln!(out, "{}", names.join(","))?;
        Ok(Self {
            out,
            columns: Some(columns),
        })
    }

    /// Writes one row: `t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz`, or
    /// the columns chosen.
    ///
    /// `body` must be a plain CSV field (no commas, quotes or line breaks):
    /// the scene checks names.
    ///
    /// # Errors
    /// The writer's errors.
    pub fn row(&mut self, body: &str, state: &BodyState) -> io::Result<()> {
        if let Some(columns) = &self.columns {
            for (k, column) in columns.iter().enumerate() {
                if k > 0 {
                    self.out.write_all(b",")?;
                }
                match column.value(state) {
                    Some(x) => write!(self.out, "{}", Shortest(x))?,
                    None => self.out.write_all(body.as_bytes())?,
                }
            }
            return self.out.write_all(b"\n");
        }
        write!(self.out, "{},{body},", Shortest(state.time))?;
        let q = state.world_from_body;
        let (w, l) = (state.omega_body, state.l_world);
        write_numbers(
            &mut self.out,
            &[
                q.w,
                q.x,
                q.y,
                q.z,
                w.x,
                w.y,
                w.z,
                state.energy,
                l.x,
                l.y,
                l.z,
            ],
        )
    }

    /// One row per state of `states` ([`read_states`]), named from
    /// `bodies` (names and ids in scene order).
    ///
    /// # Errors
    /// The writer's errors.
    pub fn rows(&mut self, states: &States, bodies: &[(String, BodyId)]) -> io::Result<()> {
        for (index, s) in states {
            self.row(&bodies[*index].0, s)?;
        }
        Ok(())
    }

    /// Flushes the writer.
    ///
    /// # Errors
    /// The writer's errors.
    pub fn flush(&mut self) -> io::Result<()> {
        self.out.flush()
    }
}

#[cfg(test)]
mod tests {
    use glam::{DQuat, DVec3};

    use super::*;

    #[test]
    fn header_and_row_in_shortest_form() {
        let mut csv = CsvWriter::with_columns(Vec::new(), Column::default_columns()).unwrap();
        let row = BodyState {
            time: 0.1 + 0.2,
            world_from_body: DQuat::from_xyzw(0.0, 0.0, -0.0, 1.0),
            omega_body: DVec3::new(0.01, 1.0, 0.0),
            energy: 1.00005,
            l_world: DVec3::new(0.01, 2.0, 1e-20),
            position: DVec3::new(1.0, -2.0, 0.5),
            velocity: DVec3::new(0.0, 0.25, -9.81),
        };
        csv.row("handle", &row).unwrap();
        csv.flush().unwrap();
        let text = String::from_utf8(csv.out).unwrap();
        assert_eq!(
            text,
            "t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz\n\
             0.30000000000000004,handle,1,0,0,0,0.01,1,0,1.00005,0.01,2,1e-20\n"
        );
    }

    #[test]
    fn chosen_columns_in_the_order_given() {
        let columns = Column::parse_list("t,x,z, vz,body,energy").unwrap();
        let mut csv = CsvWriter::with_columns(Vec::new(), columns).unwrap();
        let row = BodyState {
            time: 0.5,
            world_from_body: DQuat::IDENTITY,
            omega_body: DVec3::ZERO,
            energy: 2.5,
            l_world: DVec3::ZERO,
            position: DVec3::new(1.0, -2.0, 0.5),
            velocity: DVec3::new(0.0, 0.25, -9.81),
        };
        csv.row("ball", &row).unwrap();
        let text = String::from_utf8(csv.out).unwrap();
        assert_eq!(text, "t,x,z,vz,body,energy\n0.5,1,0.5,-9.81,ball,2.5\n");
        // The default columns, chosen explicitly, take the default path.
        let csv = CsvWriter::with_columns(Vec::new(), Column::parse_list(HEADER).unwrap()).unwrap();
        assert!(csv.columns.is_none());
        assert_eq!(Column::names(), format!("{HEADER},x,y,z,vx,vy,vz"));
    }

    #[test]
    fn bad_column_lists_say_what_is_valid() {
        let e = Column::parse_list("t,speed").unwrap_err();
        assert_eq!(
            e,
            "unknown column `speed` (valid: t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz,x,y,z,vx,vy,vz)"
        );
        assert!(
            Column::parse_list("")
                .unwrap_err()
                .starts_with("unknown column ``")
        );
        assert_eq!(
            Column::parse_list("t,t").unwrap_err(),
            "column `t` is given twice"
        );
    }
}
