//! The world's methods as `'static` integrators: a world keeps one
//! propagator per stepped body, and a propagator borrows its integrator for
//! as long as it lives, so the integrator must outlive the world.
//!
//! Every integrator of the registry ([`crate::method`],
//! [`crate::heavy_top_method`]) is a constant, so each name maps to a
//! `static` here; the tests check that the two registries agree.

use crate::composition::{Composition, KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};
use crate::splitting::{AxisStrang, SymmetricTopSplitting};
use crate::{
    DynamicsError, ExactFlow, FreeBodyIntegrator, HEAVY_TOP_METHODS, HeavyTopAuto,
    HeavyTopIntegrator, HeavyTopRk4, HeavyTopSplitting, METHODS, MoserVeselov,
    PreprocessedMoserVeselov, Rk4,
};

static SPLITTING4: Composition = Composition::new("splitting4", 4, &SUZUKI_4);
static SPLITTING6: Composition = Composition::new("splitting6", 6, &KAHAN_LI_6);
static SPLITTING8: Composition = Composition::new("splitting8", 8, &KAHAN_LI_8);
static PDMV4: PreprocessedMoserVeselov = PreprocessedMoserVeselov::ORDER_4;
static PDMV6: PreprocessedMoserVeselov = PreprocessedMoserVeselov::ORDER_6;
static PDMV8: PreprocessedMoserVeselov = PreprocessedMoserVeselov::ORDER_8;
static PDMV10: PreprocessedMoserVeselov = PreprocessedMoserVeselov::ORDER_10;
static HEAVY_STRANG: HeavyTopSplitting = HeavyTopSplitting::STRANG;
static HEAVY_SPLITTING4: HeavyTopSplitting = HeavyTopSplitting::ORDER_4;
static HEAVY_SPLITTING6: HeavyTopSplitting = HeavyTopSplitting::ORDER_6;
static HEAVY_SPLITTING8: HeavyTopSplitting = HeavyTopSplitting::ORDER_8;

/// The free-body integrator called `name` (`auto` is the exact solution).
///
/// # Errors
/// [`DynamicsError::UnknownMethod`] listing the known names.
pub(crate) fn free_body(name: &str) -> Result<&'static dyn FreeBodyIntegrator, DynamicsError> {
    Ok(match name {
        "auto" | "exact" => &ExactFlow,
        "rk4" => &Rk4,
        "strang" => &AxisStrang,
        "splitting" => &SymmetricTopSplitting,
        "splitting4" => &SPLITTING4,
        "splitting6" => &SPLITTING6,
        "splitting8" => &SPLITTING8,
        "dmv" => &MoserVeselov,
        "pdmv4" => &PDMV4,
        "pdmv6" => &PDMV6,
        "pdmv8" => &PDMV8,
        "pdmv10" => &PDMV10,
        _ => {
            return Err(DynamicsError::UnknownMethod {
                name: name.to_owned(),
                known: METHODS.join(", "),
            });
        }
    })
}

/// The heavy-top integrator called `name`.
///
/// # Errors
/// [`DynamicsError::UnknownMethod`] listing the heavy-top names.
pub(crate) fn heavy_top(name: &str) -> Result<&'static dyn HeavyTopIntegrator, DynamicsError> {
    Ok(match name {
        "auto" => &HeavyTopAuto,
        "rk4" => &HeavyTopRk4,
        "strang" => &HEAVY_STRANG,
        "splitting4" => &HEAVY_SPLITTING4,
        "splitting6" => &HEAVY_SPLITTING6,
        "splitting8" => &HEAVY_SPLITTING8,
        _ => {
            return Err(DynamicsError::UnknownMethod {
                name: name.to_owned(),
                known: HEAVY_TOP_METHODS.join(", "),
            });
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_the_registries() {
        for name in METHODS {
            let ours = free_body(name).unwrap();
            let theirs = crate::method(name).unwrap();
            assert_eq!((ours.name(), ours.order()), (theirs.name(), theirs.order()));
        }
        for name in HEAVY_TOP_METHODS {
            let ours = heavy_top(name).unwrap();
            let theirs = crate::heavy_top_method(name).unwrap();
            assert_eq!((ours.name(), ours.order()), (theirs.name(), theirs.order()));
        }
        assert!(free_body("euler").is_err());
        assert!(heavy_top("exact").is_err());
    }
}
