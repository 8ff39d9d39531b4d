//! [`TableEvent`]: what happened to a body on the table, and when —
//! recorded while the run goes on.

use std::fmt;

/// One event of a [`super::TableMotion`].
///
/// ```
/// use kreisel_dynamics::{TableEvent, TableEventKind};
/// let e = TableEvent { time: 0.42835, contact: Some(0), kind: TableEventKind::LiftOff };
/// assert_eq!(e.to_string(), "t = 0.42835 s: contact #0 lifts off");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableEvent {
    /// The time, s.
    pub time: f64,
    /// Which contact shape (`None`: the whole body, as for rest).
    pub contact: Option<usize>,
    /// What happened.
    pub kind: TableEventKind,
}

/// What a [`TableEvent`] records.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TableEventKind {
    /// The shape struck the table: `approach_speed` `−γ_N⁻` before, the
    /// normal velocity `γ_N⁺` after (m/s).
    Impact {
        /// `−γ_N⁻`, m/s.
        approach_speed: f64,
        /// `γ_N⁺`, m/s (`e · approach_speed` for a lone contact).
        rebound_speed: f64,
    },
    /// Rebounds too small to resolve (below the motion's resolution
    /// speed): the remaining bounces, flights of a constant gap
    /// acceleration `a` shortened by `e` each, accumulate at
    /// `accumulation_time = t + 2 e v/(a (1 − e))`; the contact is closed
    /// from the impact on.
    ImpactsAccumulate {
        /// The accumulation point of the bounces, s.
        accumulation_time: f64,
    },
    /// The shape reached the table without speed and stays on it.
    Touchdown,
    /// The normal force reached zero: the shape leaves the table.
    LiftOff,
    /// The slip (and drilling) stopped: the contact sticks.
    Stick,
    /// The friction force reached the cone: the contact slips.
    Slip,
    /// The rolling rate stopped: the rolling resistance holds the rolling
    /// ([`super::ContactLaw::try_with_rolling_resistance`]).
    StopsRolling,
    /// The rolling resistance reached its bound `δ N`: the body rolls.
    StartsRolling,
    /// A disk rim's axis reached the vertical: the disk lies on its face
    /// (a plastic landing), sliding and spinning on it until it stops.
    LandsFlat,
    /// The body is at rest on the table.
    Rest,
}

impl fmt::Display for TableEvent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "t = {} s: ", self.time)?;
        match self.contact {
            Some(i) => write!(f, "contact #{i} ")?,
            None => f.write_str("the body ")?,
        }
        match self.kind {
            TableEventKind::Impact {
                approach_speed,
                rebound_speed,
            } => write!(
                f,
                "strikes the table at {approach_speed:e} m/s, rebounds at {rebound_speed:e} m/s"
            ),
            TableEventKind::ImpactsAccumulate { accumulation_time } => {
                write!(f, "bounces accumulate at t = {accumulation_time} s")
            }
            TableEventKind::Touchdown => f.write_str("touches down"),
            TableEventKind::LiftOff => f.write_str("lifts off"),
            TableEventKind::Stick => f.write_str("sticks"),
            TableEventKind::Slip => f.write_str("slips"),
            TableEventKind::StopsRolling => f.write_str("stops rolling"),
            TableEventKind::StartsRolling => f.write_str("starts rolling"),
            TableEventKind::LandsFlat => f.write_str("lands flat on its face"),
            TableEventKind::Rest => f.write_str("comes to rest"),
        }
    }
}
