//! The CSV that `kreisel simulate` writes: a header, then one row per body
//! and output time, streamed.

#![forbid(unsafe_code)]

use std::io::{self, Write};

use glam::{DQuat, DVec3};
use kreisel_dynamics::{BodyId, World};

use crate::numbers::{Shortest, write_numbers};

/// The header line, without its newline.
pub const HEADER: &str = "t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz";

/// The numbers of one row after the time and the body name.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// Attitude: maps body coordinates to world coordinates.
    pub world_from_body: DQuat,
    /// Angular velocity in body axes, rad/s.
    pub omega_body: DVec3,
    /// Total energy, J.
    pub energy: f64,
    /// Angular momentum about the centre of mass in world axes, kg·m²/s.
    pub l_world: DVec3,
}

/// Writes the header and the rows to `out` (which should be buffered).
#[derive(Debug)]
pub struct CsvWriter<W: Write> {
    out: W,
}

impl<W: Write> CsvWriter<W> {
    /// Writes the header line.
    ///
    /// # Errors
    /// The writer's errors.
    pub fn new(mut out: W) -> io::Result<Self> {
        writeln!(out, "{HEADER}")?;
        Ok(Self { out })
    }

    /// Writes one row: `t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz`.
    ///
    /// `body` must be a plain CSV field (no commas, quotes or line breaks):
    /// the scene checks names.
    ///
    /// # Errors
    /// The writer's errors.
    pub fn row(&mut self, t: f64, body: &str, row: &Row) -> io::Result<()> {
        write!(self.out, "{},{body},", Shortest(t))?;
        let q = row.world_from_body;
        let (w, l) = (row.omega_body, row.l_world);
        write_numbers(
            &mut self.out,
            &[q.w, q.x, q.y, q.z, w.x, w.y, w.z, row.energy, l.x, l.y, l.z],
        )
    }

    /// One row per body of `world` at its current time, `bodies` (names
    /// and ids) in scene order.
    ///
    /// # Errors
    /// The writer's errors.
    pub fn rows(&mut self, world: &World, bodies: &[(String, BodyId)]) -> io::Result<()> {
        for (name, id) in bodies {
            // Every id comes from this world.
            let Some(s) = world.state(*id) else { continue };
            let row = Row {
                world_from_body: s.world_from_body,
                omega_body: s.omega_body,
                energy: s.energy,
                l_world: s.l_world,
            };
            self.row(s.time, name, &row)?;
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
    use super::*;

    #[test]
    fn header_and_row_in_shortest_form() {
        let mut csv = CsvWriter::new(Vec::new()).unwrap();
        let row = Row {
            world_from_body: DQuat::from_xyzw(0.0, 0.0, -0.0, 1.0),
            omega_body: DVec3::new(0.01, 1.0, 0.0),
            energy: 1.00005,
            l_world: DVec3::new(0.01, 2.0, 1e-20),
        };
        csv.row(0.1 + 0.2, "handle", &row).unwrap();
        csv.flush().unwrap();
        let text = String::from_utf8(csv.out).unwrap();
        assert_eq!(
            text,
            "t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz\n\
             0.30000000000000004,handle,1,0,0,0,0.01,1,0,1.00005,0.01,2,1e-20\n"
        );
    }
}
