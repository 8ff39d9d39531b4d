"""Closed-form references for bodies bouncing on the table z = 0.

Regenerate (from the repository root; mpmath 1.3.0, see requirements.txt):

    python3 tests/data/gen/table_closed_forms.py

Writes ../contact/bouncing_ball.csv and ../contact/superball.csv (relative to
this script). Every number is computed with mpmath at 30 significant digits
and written as the nearest f64 (repr(float(x)), shortest round-trip form).
The script asserts the conserved quantities below at 1e-25 before it writes.

1. Bouncing ball (bouncing_ball.csv)
------------------------------------
A ball of radius r = 0.1 m, centre dropped from rest at h0 = 1.0 m above the
table, g = 9.81 m/s^2, Newton restitution e = 0.9, no spin, no friction needed
(the contact point has no tangential velocity). Fall height d = h0 - r.

    v1      = sqrt(2 g d)                  speed at the first impact
    t1      = sqrt(2 d / g)                first impact time
    v_n^-   = -e^(n-1) v1,  v_n^+ = e^n v1  vertical velocity before/after impact n
    t_(n+1) = t_n + 2 e^n v1 / g           (flight time of the n-th hop)
    apex n  : time t_n + e^n v1 / g, centre at r + e^(2n) d,
              bottom of the ball e^(2n) d above the table
    t_inf   = t1 + 2 e v1 / (g (1 - e))    Zeno time: the impacts accumulate there

Columns: n, t (impact n), v_before, v_after, t_apex, apex_centre, apex_bottom,
t_inf (the same in every row). The t_n are summed hop by hop (not taken from
the geometric-series formula), and the script checks they agree with
t_n = t1 + (2 v1/g) e (1 - e^(n-1)) / (1 - e) and tend to t_inf.

2. Garwin's superball (superball.csv; Am. J. Phys. 37 (1969) 88)
----------------------------------------------------------------
A uniform solid sphere, radius R = 0.03 m, mass m = 1 kg (every column scales
with m except the velocities: momenta and energies are per kilogram),
I = 2/5 m R^2, centre R above the plane z = 0, g = 9.81 m/s^2.
Motion in the x-z plane, spin about y.

Sign convention (derived): with omega = wy * y_hat and the contact point at
rho = -R z_hat from the centre, the contact point's velocity is
v + omega x rho = v - R wy (y_hat x z_hat) = v - R wy x_hat, so its tangential
slip is

    u = vx - R * wy          (u = 0 is rolling; wy > 0 rolls the ball toward +x).

Impact map (rigid, instantaneous; the impulse P = (Px, 0, Pz) acts AT the
contact point; no slip limit, i.e. unbounded friction; vz^+ = -e_n vz^-,
u^+ = -e_t u^-). Newton-Euler for impulses: m dv = P, I dw = rho x P, with
(rho x P)_y = -R Px, so dwy = -R Px / I and du = Px (1/m + R^2/I) = 7 Px/(2m):

    vz^+ = -e_n vz^-
    vx^+ = vx^- - (2/7) (1 + e_t) u^-
    wy^+ = wy^- + (5/7) (1 + e_t) u^- / R
    (check: u^+ = vx^+ - R wy^+ = u^- - (1 + e_t) u^- = -e_t u^-)

Conserved through every impact (asserted):
* angular momentum about the contact point, y component:
  L_c = I wy + m R vx  (rho x ... : (R z_hat x m v)_y = m R vx);
  the impulse acts at that point, so its moment about it is zero.
* kinetic energy E = m (vx^2 + vz^2)/2 + I wy^2/2, when e_n = e_t = 1
  (the map is then a reflection in the kinetic-energy metric).
  For e_n, e_t < 1 the energy must not rise (asserted too).

Between impacts the ball flies freely: vx, wy constant, vz^- of the next
impact = -vz^+, flight time 2 vz^+ / g, x advances by vx^+ times that.

Initial state (choice of this reference): at t = 0 the ball touches the table
(centre at x = 0, z = R) moving with (vx, vz) = (2, -3) m/s and wy = +20 rad/s,
i.e. the first impact is at t = 0 (u^- = 2 - 0.03*20 = 1.4 m/s).
Cases: `en0.9_et0.8` (e_n = 0.9, e_t = 0.8) and `en1_et1` (e_n = e_t = 1).
Rows k = 1..10 give impact k: its time t, the centre's x, the states just
before (vx_before, vz_before, wy_before, u_before) and just after
(vx_after, vz_after, wy_after, u_after), L_c and E before and after.
"""

import csv
from pathlib import Path

import mpmath as mp

mp.mp.dps = 30
OUT = Path(__file__).resolve().parent.parent / "contact"
TOL = mp.mpf("1e-25")


def f(x):
    """The nearest f64, in its shortest round-trip form."""
    return repr(float(x))


def bouncing_ball():
    g, h0, r, e = mp.mpf("9.81"), mp.mpf("1.0"), mp.mpf("0.1"), mp.mpf("0.9")
    d = h0 - r
    v1 = mp.sqrt(2 * g * d)
    t1 = mp.sqrt(2 * d / g)
    t_inf = t1 + 2 * e * v1 / (g * (1 - e))
    rows = []
    t = t1
    for n in range(1, 61):
        closed = t1 + (2 * v1 / g) * e * (1 - e ** (n - 1)) / (1 - e)
        assert abs(t - closed) < TOL, (n, t, closed)
        assert t < t_inf
        v_before = -(e ** (n - 1)) * v1
        v_after = e**n * v1
        # energy after = e^2 times energy before (Newton restitution)
        assert abs(v_after**2 - e**2 * v_before**2) < TOL
        t_apex = t + v_after / g
        apex_bottom = e ** (2 * n) * d
        # apex from the ballistic flight, checked against the closed form
        assert abs(v_after**2 / (2 * g) - apex_bottom) < TOL
        rows.append(
            [n, t, v_before, v_after, t_apex, r + apex_bottom, apex_bottom, t_inf]
        )
        t += 2 * v_after / g
        # now t = t_(n+1); what is left to the Zeno time is the geometric tail
        assert abs((t_inf - t) - 2 * e ** (n + 1) * v1 / (g * (1 - e))) < TOL
    path = OUT / "bouncing_ball.csv"
    with path.open("w", newline="") as fh:
        fh.write(
            "# tests/data/gen/table_closed_forms.py: ball r = 0.1 m dropped from "
            "centre height 1.0 m, e = 0.9, g = 9.81 (mpmath, 30 digits)\n"
        )
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(
            [
                "n",
                "t",
                "v_before",
                "v_after",
                "t_apex",
                "apex_centre",
                "apex_bottom",
                "t_inf",
            ]
        )
        for row in rows:
            w.writerow([row[0], *map(f, row[1:])])
    return path


def superball_case(name, e_n, e_t):
    g, R, m = mp.mpf("9.81"), mp.mpf("0.03"), mp.mpf(1)
    inertia = mp.mpf(2) / 5 * m * R**2
    vx, vz, wy = mp.mpf(2), mp.mpf(-3), mp.mpf(20)
    t, x = mp.mpf(0), mp.mpf(0)

    def lc(vx, wy):
        return inertia * wy + m * R * vx

    def energy(vx, vz, wy):
        return m * (vx**2 + vz**2) / 2 + inertia * wy**2 / 2

    rows = []
    for k in range(1, 11):
        u = vx - R * wy
        vx1 = vx - mp.mpf(2) / 7 * (1 + e_t) * u
        vz1 = -e_n * vz
        wy1 = wy + mp.mpf(5) / 7 * (1 + e_t) * u / R
        u1 = vx1 - R * wy1
        assert abs(u1 + e_t * u) < TOL
        # the impact from the impulse directly (independent of the formulas above)
        px = -(1 + e_t) * u / (1 / m + R**2 / inertia)
        assert abs(vx1 - (vx + px / m)) < TOL
        assert abs(wy1 - (wy - R * px / inertia)) < TOL
        lc0, lc1 = lc(vx, wy), lc(vx1, wy1)
        assert abs(lc1 - lc0) < TOL, (name, k, lc0, lc1)
        e0, e1 = energy(vx, vz, wy), energy(vx1, vz1, wy1)
        if e_n == 1 and e_t == 1:
            assert abs(e1 - e0) < TOL, (name, k, e0, e1)
        else:
            assert e1 <= e0 + TOL
        rows.append([name, k, t, x, vx, vz, wy, u, vx1, vz1, wy1, u1, lc0, lc1, e0, e1])
        flight = 2 * vz1 / g
        t += flight
        x += vx1 * flight
        vx, vz, wy = vx1, -vz1, wy1
    return rows


def superball():
    rows = superball_case("en0.9_et0.8", mp.mpf("0.9"), mp.mpf("0.8"))
    rows += superball_case("en1_et1", mp.mpf(1), mp.mpf(1))
    path = OUT / "superball.csv"
    with path.open("w", newline="") as fh:
        fh.write(
            "# tests/data/gen/table_closed_forms.py: Garwin superball R = 0.03 m, "
            "m = 1 kg, I = 2/5 m R^2, u = vx - R*wy, impacts at the contact point "
            "(first impact at t = 0, x = 0; mpmath, 30 digits)\n"
        )
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(
            [
                "case",
                "k",
                "t",
                "x",
                "vx_before",
                "vz_before",
                "wy_before",
                "u_before",
                "vx_after",
                "vz_after",
                "wy_after",
                "u_after",
                "lc_before",
                "lc_after",
                "energy_before",
                "energy_after",
            ]
        )
        for row in rows:
            w.writerow([row[0], row[1], *map(f, row[2:])])
    return path


if __name__ == "__main__":
    for p in (bouncing_ball(), superball()):
        print("wrote", p)
