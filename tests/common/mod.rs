//! Shared test problems of the root package's tests: the committed
//! reference data under `tests/data/` ([`Table`]) and Leine & Glocker's
//! tippe top ([`tippe_top`]), defined once with the test problems of
//! kreisel-dynamics (`crates/dynamics/tests/common/`), and meshes of
//! primitive solids ([`shapes`]).
#![allow(dead_code)]

#[path = "../../crates/dynamics/tests/common/reference_csv.rs"]
mod reference_csv;
pub mod shapes;
#[path = "../../crates/dynamics/tests/common/tippe_top.rs"]
pub mod tippe_top;

// Not every test that declares `common` reads a table.
#[allow(unused_imports)]
pub use reference_csv::Table;

/// `a − b` wrapped into `(−π, π]`: the distance between two angles.
pub fn angle_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    if d > std::f64::consts::PI {
        d - std::f64::consts::TAU
    } else {
        d
    }
}
