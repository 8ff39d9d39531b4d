//! What the contacts' problem is made of, shared by its solvers (block
//! Gauss–Seidel in `contact_problem`, the active set, the rolling cones'
//! sweeps, Newton's method on the whole): each touching contact's block
//! and law, what is known of its rolling, and the Delassus product over
//! the blocks.
//!
//! ```text
//! y_i = y⁰_i + Σ_j G_ij x_j      (G the Delassus operator, x the forces or impulses)
//! ```

use glam::DVec3;

/// One contact's share of a set-valued problem: its Delassus block and
/// its law.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Block {
    /// How many components: 1 + friction directions.
    pub(crate) size: usize,
    pub(crate) mu: f64,
    /// `Some(d)`: slipping already along `d` (the friction is `−μ x_N d`);
    /// `None`: the friction cone.
    pub(crate) slipping: Option<DVec3>,
}

/// What is known of a touching contact's rolling before the solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Rolling {
    /// The law has no rolling resistance.
    Free,
    /// The rolling's cone decides: hold or roll.
    Cone,
    /// Rolling already along `d` (its rate resolved): `x_R = −x_N d`.
    Along(DVec3),
}

/// `y += G x` over the blocks' components (`g(i, a, j, b)` the entry
/// between component `a` of block `i` and component `b` of block `j`).
pub(crate) fn add_delassus_product(
    y: &mut [[f64; 4]],
    blocks: &[Block],
    g: &dyn Fn(usize, usize, usize, usize) -> f64,
    x: &[[f64; 4]],
) {
    for (i, yi) in y.iter_mut().enumerate() {
        for (a, v) in yi.iter_mut().enumerate().take(blocks[i].size) {
            for (j, xj) in x.iter().enumerate() {
                for (b, xb) in xj.iter().enumerate().take(blocks[j].size) {
                    *v += g(i, a, j, b) * xb;
                }
            }
        }
    }
}
