//! Elliptic integrals and Jacobi elliptic functions in `f64`, accurate near
//! the separatrix (`mc = 1 − m → 0`), for the exact free-rigid-body solution.
//!
//! - Carlson's symmetric integrals [`carlson_rf`], [`carlson_rd`],
//!   [`carlson_rj`] (Cauchy principal value for `p < 0`), [`carlson_rc`] by
//!   the duplication theorem with the 7th-order series of Carlson (1995).
//! - Legendre's complete integrals [`complete_k`], [`complete_e`],
//!   [`complete_pi`] and incomplete [`incomplete_f`], [`incomplete_e`],
//!   [`incomplete_pi`] (any amplitude φ, by quasi-periodicity), each also
//!   `…_complementary`, taking `mc = 1 − m` so that `mc` down to 5·10⁻³²⁴ keeps
//!   full accuracy (an f64 `m` cannot come closer to 1 than 1.1·10⁻¹⁶).
//! - Jacobi's [`jacobi_sn_cn_dn`], [`jacobi_sn_cn_dn_m`], [`jacobi_amplitude`]
//!   and [`JacobiElliptic`] for many arguments at one parameter: Bulirsch's
//!   descending Landen/AGM method on `mc`, with `u` reduced modulo 2K in
//!   double-double, so the accuracy does not degrade with `|u|`.
//!
//! ## Conventions
//! Parameter `m = k²` (as DLMF and mpmath, not the modulus k), complementary
//! parameter `mc = 1 − m`; Π's characteristic `n` enters as `1 − n sin²θ`.
//! Arguments outside the domain give NaN, like [`f64::sqrt`]; poles give
//! `±∞`. Nothing panics.
//!
//! | function | domain | at the boundary |
//! |---|---|---|
//! | [`carlson_rf`]`(x, y, z)` | x, y, z ≥ 0, at most one 0 | two zeros: +∞ |
//! | [`carlson_rd`]`(x, y, z)` | x, y ≥ 0 (at most one 0), z > 0 | z = 0: +∞ |
//! | [`carlson_rj`]`(x, y, z, p)` | x, y, z ≥ 0 (at most one 0), p ≠ 0 | p < 0: principal value |
//! | [`carlson_rc`]`(x, y)` | x ≥ 0, y ≠ 0 | y < 0: principal value |
//! | [`complete_k`]`(m)`, [`complete_e`]`(m)` | m ≤ 1 | K(1) = +∞, E(1) = 1 |
//! | [`complete_pi`]`(n, m)` | m ≤ 1, n ≠ 1 | n > 1: principal value |
//! | [`incomplete_f`]`(φ, m)` etc. | any finite φ for m ≤ 1; m sin²φ ≤ 1 for m > 1 | |
//! | [`jacobi_sn_cn_dn`]`(u, mc)` | any finite u, any finite mc | mc = 0: tanh, sech, sech |
//!
//! ## Why the complementary parameter
//! Near the separatrix of the free rigid body (energy close to that of the
//! rotation about the middle axis) the parameter `m` of its Jacobi solution
//! tends to 1. An f64 `m` cannot resolve `1 − m` below 1.1·10⁻¹⁶ and forming
//! `1 − m` from it loses all digits of `mc` below 10⁻¹⁶·m; K then has its
//! logarithmic singularity `K ≈ ln(4/√mc)`. Every `…_complementary` function
//! and [`jacobi_sn_cn_dn`] therefore take `mc` itself: `K = R_F(0, mc, 1)`,
//! the AGM starts from `(1, √mc)`, and the expansions about tanh/sech use
//! `mc` directly, so `mc = 10⁻³⁰⁰` is as accurate as `mc = 0.5`.
//!
//! ## Accuracy
//! Measured against 40–370-digit mpmath values (`tests/data/gen/elliptic.py`,
//! `cargo test -p kreisel-dynamics --test elliptic -- --nocapture`):
//!
//! | functions | max error measured |
//! |---|---|
//! | R_F, R_D, R_J (p > 0), R_C, K, E, F(φ), E(φ) | ≤ 7·10⁻¹⁶ relative |
//! | R_J (p < 0), Π(n), Π(n; φ) | ≤ 2.3·10⁻¹⁵ relative |
//! | sn, cn, dn, mc ∈ [5·10⁻³²⁴, 1], \|u\| ≤ 10⁶ | ≤ 5·10⁻¹⁶ absolute; dn ≤ 2·10⁻¹⁵ relative |
//!
//! ```
//! use kreisel_dynamics::elliptic::{complete_k_complementary, jacobi_sn_cn_dn};
//! // Close to the separatrix the motion is tanh/sech for |u| ≪ K ≈ 346.
//! let mc = 1e-300;
//! assert!((complete_k_complementary(mc) - 346.774_058_310_226_7).abs() < 1e-12);
//! let (sn, cn, dn) = jacobi_sn_cn_dn(3.0, mc);
//! assert!((sn - 3.0f64.tanh()).abs() < 1e-16 && (cn - dn).abs() < 1e-17);
//! ```
//!
//! The Jacobi functions solve Euler's equations of the free rigid body in the
//! form `s′ = c d`, `c′ = −s d`, `d′ = −m s c` (Celledoni et al. 2008),
//! here checked by central differences right at the separatrix:
//!
//! ```
//! use kreisel_dynamics::elliptic::JacobiElliptic;
//! let mc = 1e-200;
//! let f = JacobiElliptic::new(mc);
//! let h = 1e-6;
//! for u in [0.3, 7.0, 150.0, 229.5, 1000.0] {
//!     let (s, c, d) = f.sn_cn_dn(u);
//!     let (sp, cp, dp) = f.sn_cn_dn(u + h);
//!     let (sm, cm, dm) = f.sn_cn_dn(u - h);
//!     let step = (u + h) - (u - h);
//!     assert!(((sp - sm) / step - c * d).abs() < 1e-8);
//!     assert!(((cp - cm) / step + s * d).abs() < 1e-8);
//!     assert!(((dp - dm) / step + (1.0 - mc) * s * c).abs() < 1e-8);
//! }
//! ```
//!
//! ## References
//! - B. C. Carlson, "Numerical computation of real or complex elliptic
//!   integrals", Numer. Algorithms 10:13–26 (1995).
//! - R. Bulirsch, "Numerical calculation of elliptic integrals and elliptic
//!   functions", Numer. Math. 7:78–90 (1965).
//! - NIST Digital Library of Mathematical Functions (DLMF), chapters 19 and 22.
//! - E. Celledoni, F. Fassò, N. Säfström, A. Zanna, "The exact computation of
//!   the free rigid body motion and its use in splitting methods", SIAM J.
//!   Sci. Comput. 30:2084–2112 (2008).

mod agm;
mod carlson;
mod complete;
pub(crate) mod dd;
mod incomplete;
mod jacobi;

pub use carlson::{carlson_rc, carlson_rd, carlson_rf, carlson_rj};
pub use complete::{
    complete_e, complete_e_complementary, complete_k, complete_k_complementary, complete_pi,
    complete_pi_complementary,
};
pub use incomplete::{
    incomplete_e, incomplete_e_complementary, incomplete_f, incomplete_f_complementary,
    incomplete_pi, incomplete_pi_complementary,
};
pub use jacobi::{JacobiElliptic, jacobi_amplitude, jacobi_sn_cn_dn, jacobi_sn_cn_dn_m};
