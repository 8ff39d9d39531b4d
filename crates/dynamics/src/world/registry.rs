//! The world's methods as `'static` integrators: a world keeps one
//! propagator per stepped body, and a propagator borrows its integrator for
//! as long as it lives, so the integrator must outlive the world.
//!
//! Every integrator is a constant, so each [`FreeBodyMethod`] and
//! [`HeavyTopMethod`] maps to a `static` here (the matches are exhaustive:
//! a new method does not compile until it is added); the tests check that
//! they agree with the methods' own `integrator()`.

use crate::composition::{Composition, KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};
use crate::splitting::{AxisStrang, SymmetricTopSplitting};
use crate::{
    ExactFlow, FreeBodyIntegrator, FreeBodyMethod, HeavyTopAuto, HeavyTopIntegrator,
    HeavyTopMethod, HeavyTopRk4, HeavyTopSplitting, HeavyTopTaylor, MoserVeselov,
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
/// The Taylor series of the whole heavy top, which a tolerance may choose
/// ([`crate::Plan::HeavyTopSeries`]).
pub(crate) static HEAVY_TAYLOR: HeavyTopTaylor = HeavyTopTaylor::DEFAULT;

/// The integrator that runs free-body method `method` (`auto`: the exact
/// solution).
pub(crate) fn free_body(method: FreeBodyMethod) -> &'static dyn FreeBodyIntegrator {
    match method {
        FreeBodyMethod::Auto | FreeBodyMethod::Exact => &ExactFlow,
        FreeBodyMethod::Rk4 => &Rk4,
        FreeBodyMethod::Strang => &AxisStrang,
        FreeBodyMethod::Splitting => &SymmetricTopSplitting,
        FreeBodyMethod::Splitting4 => &SPLITTING4,
        FreeBodyMethod::Splitting6 => &SPLITTING6,
        FreeBodyMethod::Splitting8 => &SPLITTING8,
        FreeBodyMethod::Dmv => &MoserVeselov,
        FreeBodyMethod::Pdmv4 => &PDMV4,
        FreeBodyMethod::Pdmv6 => &PDMV6,
        FreeBodyMethod::Pdmv8 => &PDMV8,
        FreeBodyMethod::Pdmv10 => &PDMV10,
    }
}

/// The integrator that runs heavy-top method `method`.
pub(crate) fn heavy_top(method: HeavyTopMethod) -> &'static (dyn HeavyTopIntegrator + Sync) {
    match method {
        HeavyTopMethod::Auto => &HeavyTopAuto,
        HeavyTopMethod::Rk4 => &HeavyTopRk4,
        HeavyTopMethod::Strang => &HEAVY_STRANG,
        HeavyTopMethod::Splitting4 => &HEAVY_SPLITTING4,
        HeavyTopMethod::Splitting6 => &HEAVY_SPLITTING6,
        HeavyTopMethod::Splitting8 => &HEAVY_SPLITTING8,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agrees_with_the_methods() {
        for m in FreeBodyMethod::ALL {
            let (ours, theirs) = (free_body(m), m.integrator());
            assert_eq!((ours.name(), ours.order()), (theirs.name(), theirs.order()));
        }
        for m in HeavyTopMethod::ALL {
            let (ours, theirs) = (heavy_top(m), m.integrator());
            assert_eq!((ours.name(), ours.order()), (theirs.name(), theirs.order()));
        }
    }
}
