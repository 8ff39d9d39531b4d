//! What `kreisel simulate --plot` keeps of a run: per body (the first
//! [`MAX_BODIES`] of the scene) its rows' times, ω in body axes, energy and
//! angular momentum in body axes, thinned to at most [`MAX_POINTS`] rows so
//! memory stays bounded however long the run.
//!
//! Thinning: every row is kept until there are `2 · MAX_POINTS / 2` of them;
//! then every other kept row is dropped and only every 2nd row after it is
//! kept, and so on (the kept rows stay evenly spaced). The last row of the
//! run is always kept.

use kreisel_dynamics::{BodyId, BodyState, Support, World};
use kreisel_inertia::PrincipalAxes;

/// Bodies drawn at most (the first ones in scene order).
pub const MAX_BODIES: usize = 4;

/// Rows kept per body at most (after thinning, at least half of it).
pub const MAX_POINTS: usize = 4000;

/// What a body is, for the figure.
#[derive(Debug, Clone)]
pub struct Track {
    /// The body's name.
    pub name: String,
    /// Principal moments (ascending) and axes (body_from_principal) about the centre of mass.
    pub principal: PrincipalAxes,
    /// Turns about a fixed pivot (L is then about the pivot).
    pub pivot: bool,
    /// Stands on the ground plane or the table (L about the centre of
    /// mass, turned by the contact forces).
    pub ground: bool,
    /// Torques, forces or damping act on it.
    pub driven: bool,
    /// The kept rows, in time order.
    pub samples: Vec<BodyState>,
}

/// Collects the rows of a run for the figure.
#[derive(Debug)]
pub struct Recorder {
    /// The recorded bodies are the scene's first `recorded`.
    recorded: usize,
    /// The tracks, one per recorded body.
    pub tracks: Vec<Track>,
    /// The number of bodies in the scene.
    pub scene_bodies: usize,
    /// Rows seen so far.
    rows: u64,
    /// Every `stride`-th row is kept.
    stride: u64,
    /// The latest row when it was not kept (appended at the end).
    last: Option<Vec<BodyState>>,
}

impl Recorder {
    /// A recorder for the first [`MAX_BODIES`] of `bodies` (names and ids in
    /// scene order) in `world`.
    pub fn new(world: &World, bodies: &[(String, BodyId)]) -> Self {
        let chosen: Vec<&(String, BodyId)> = bodies.iter().take(MAX_BODIES).collect();
        let tracks = chosen
            .iter()
            .filter_map(|(name, id)| {
                let body = world.body(*id)?;
                Some(Track {
                    name: name.clone(),
                    principal: body.mass_properties().principal(),
                    pivot: matches!(body.support(), Support::Pivot { .. }),
                    ground: matches!(
                        body.support(),
                        Support::Ground { .. } | Support::Table { .. }
                    ),
                    driven: !body.inputs().is_none(),
                    samples: Vec::new(),
                })
            })
            .collect();
        Self {
            recorded: chosen.len(),
            tracks,
            scene_bodies: bodies.len(),
            rows: 0,
            stride: 1,
            last: None,
        }
    }

    /// Notes the rows of one time (the states [`kreisel_scene::columns::read_states`]
    /// read).
    pub fn record(&mut self, states: &kreisel_scene::columns::States) {
        let samples: Vec<BodyState> = states
            .iter()
            .filter(|(index, _)| *index < self.recorded)
            .map(|(_, s)| *s)
            .collect();
        let keep = self.rows.is_multiple_of(self.stride);
        self.rows += 1;
        if !keep {
            self.last = Some(samples);
            return;
        }
        self.last = None;
        for (track, sample) in self.tracks.iter_mut().zip(samples) {
            track.samples.push(sample);
        }
        if self
            .tracks
            .first()
            .is_some_and(|t| t.samples.len() >= MAX_POINTS)
        {
            for track in &mut self.tracks {
                let mut k = 0;
                track.samples.retain(|_| {
                    k += 1;
                    k % 2 == 1
                });
            }
            self.stride *= 2;
        }
    }

    /// The tracks, with the run's last row, and how they were thinned.
    pub fn finish(mut self) -> (Vec<Track>, Recorded) {
        if let Some(last) = self.last.take() {
            for (track, sample) in self.tracks.iter_mut().zip(last) {
                track.samples.push(sample);
            }
        }
        let recorded = Recorded {
            scene_bodies: self.scene_bodies,
            rows: self.rows,
            stride: self.stride,
        };
        (self.tracks, recorded)
    }
}

/// What a [`Recorder`] saw besides the tracks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Recorded {
    /// The number of bodies in the scene.
    pub scene_bodies: usize,
    /// Rows per body in the CSV.
    pub rows: u64,
    /// Every `stride`-th row is in the tracks (and the last).
    pub stride: u64,
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use kreisel_dynamics::Body;

    #[test]
    fn thins_evenly_and_keeps_the_last_row() {
        let mut world = World::try_new(DVec3::ZERO, 0.01).unwrap();
        let body = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0))
            .omega_body(DVec3::new(0.1, 1.0, 0.0))
            .try_build()
            .unwrap();
        let id = world.add(body).unwrap();
        let bodies = vec![("b".to_owned(), id)];
        let mut recorder = Recorder::new(&world, &bodies);
        let rows = 3 * MAX_POINTS + 7;
        let mut states = Vec::new();
        for _ in 0..rows {
            kreisel_scene::columns::read_states(&world, &bodies, &mut states);
            recorder.record(&states);
            world.advance_steps(1).unwrap();
        }
        let (tracks, recorded) = recorder.finish();
        assert_eq!(recorded.scene_bodies, 1);
        assert_eq!(recorded.rows, rows as u64);
        assert_eq!(recorded.stride, 4);
        let s = &tracks[0].samples;
        assert!(
            s.len() <= MAX_POINTS + 1 && s.len() >= MAX_POINTS / 2,
            "{}",
            s.len()
        );
        // Evenly spaced, then the last row.
        let step = s[1].time - s[0].time;
        for w in s[..s.len() - 1].windows(2) {
            assert!((w[1].time - w[0].time - step).abs() < 1e-9);
        }
        let last = (rows - 1) as f64 * 0.01;
        assert!((s.last().unwrap().time - last).abs() < 1e-9);
        assert!(!tracks[0].pivot && !tracks[0].driven && !tracks[0].ground);
        // L in body axes is I ω.
        let l = s[0].l_body();
        assert!((l - DVec3::new(0.1, 2.0, 0.0)).length() < 1e-15, "{l}");
    }
}
