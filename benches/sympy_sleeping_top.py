"""The sleeping top's linear stability the way sympy.physics.mechanics
users get it, side by side with kreisel-analysis (BENCHMARKS.md,
"Stability (issue 28)"): Kane's equations of a symmetric top on a pivot
(body-fixed XYZ angles q, body-axis rates u), `KanesMethod.linearize` at
the upright top spinning at Ω (q = 0, u = (0, 0, Ω): a relative
equilibrium, q₃ advances), the numbers substituted, the eigenvalues of A.

    python3 benches/sympy_sleeping_top.py

Prints the time of each phase and the eigenvalues against the closed form
(notes §3.11): below the threshold the growth rate √(4I₁Mgl − I₃²Ω²)/(2I₁).

What it shows (2026-11-29, sympy 1.14): the pipeline takes about 0.4 s of
symbolic work, and the eigenvalues of its A are not the motion's — at
0.8 Ω_c they are ±2.007i, ±16.29i (all imaginary) where the top grows at
3.431 /s. The spinning top is a relative equilibrium, not an equilibrium
of (q, u): the body-axis rates u₁, u₂ turn with q₃ = Ω t against the tilts
q₁, q₂, so the linearised system is periodic and A at one instant does
not decide stability (sympy's linearize takes any operating point without
a word; Drake's Linearize would refuse it as not an equilibrium). kreisel
reduces by the symmetry first (Euler–Poisson variables), where the
sleeping top is an equilibrium.
"""

import math
import time

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me

M, G, L = 1.0, 9.81, 0.1
I1_CM, I3 = 0.02, 0.01
I1 = I1_CM + M * L * L          # about the pivot


def main():
    t0 = time.perf_counter()
    q = me.dynamicsymbols("q1:4")
    u = me.dynamicsymbols("u1:4")
    m, g, l, a, c, w = sm.symbols("m g l a c w")   # a = I₁ about the pivot, c = I₃, w = Ω
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Body", q, "XYZ")
    B.set_ang_vel(N, u[0] * B.x + u[1] * B.y + u[2] * B.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    G_ = O.locatenew("G", l * B.z)
    G_.v2pt_theory(O, N, B)
    inertia = me.inertia(B, a, a, c)
    # RigidBody wants the inertia about G: a − m l² across, c along.
    top = me.RigidBody("top", G_, B, m, (inertia - m * l**2 * me.inertia(B, 1, 1, 0), G_))
    kde = me.kinematic_equations(list(u), list(q), "Body", "XYZ")
    forces = [(G_, -m * g * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kde)
    kane.kanes_equations([top], forces)
    t1 = time.perf_counter()
    # The operating point must be given: without it sympy linearises at
    # q = u = 0 (no spin) without a word.
    op_point = {q[0]: 0, q[1]: 0, q[2]: 0, u[0]: 0, u[1]: 0, u[2]: w}
    A, _ = kane.linearize(op_point=op_point, A_and_B=True)[:2]
    # The q̇ left in A (sympy#20486): replaced by their expressions in q, u.
    A = A.subs(kane.kindiffdict())
    t2 = time.perf_counter()
    return kane, A, (m, g, l, a, c, w), (t0, t1, t2)


def evaluate(A, symbols, spin):
    m, g, l, a, c, w = symbols
    op = {m: M, g: G, l: L, a: I1, c: I3, w: spin}
    return np.array(A.subs(op).evalf(), dtype=float)


if __name__ == "__main__":
    _, A, symbols, (t0, t1, t2) = main()
    critical = math.sqrt(4 * I1 * M * G * L) / I3
    for factor in (0.8, 2.0):
        spin = factor * critical
        t3 = time.perf_counter()
        a = evaluate(A, symbols, spin)
        t4 = time.perf_counter()
        lam = np.linalg.eigvals(a)
        t5 = time.perf_counter()
        growth = max(lam.real)
        expected = math.sqrt(max(0.0, 4 * I1 * M * G * L - (I3 * spin) ** 2)) / (2 * I1)
        print(f"Ω = {factor} Ω_c: largest Re λ {growth:.12g} 1/s (closed form {expected:.12g}); "
              f"|Im λ| {sorted(set(np.round(abs(lam.imag), 9)))}")
        print(f"  substitute {t4 - t3:.3f} s, eigenvalues {t5 - t4:.6f} s")
    print(f"Kane's equations {t1 - t0:.3f} s, linearize {t2 - t1:.3f} s")
