"""Reference runs of Kane & Levinson's rattleback rolling without slipping.

Regenerate (from the repository root; scipy, numpy; 1-3 minutes):

    python3 tests/data/gen/rattleback.py

Writes ../contact/rattleback.csv and ../contact/rattleback_modes.csv
(relative to this script) and prints the checks.

Physics (written in BODY axes with Poisson's variables, not from kreisel's
world-axes contact-force solve K F = b)
------------------------------------------------------------------------
* Body: mass m, inertia I about the centre of mass in body axes (z up at
  rest, I_xy = +2e-5 kg m^2: Kane & Levinson's D = -2e-5 is the entry of
  their axes whose b3 points into the table; see crates/dynamics/tests/contact_rattleback.rs),
  an ellipsoid with semi-axes E = diag(a, b, c) centred at c_e = (0, 0, 0.01)
  from the centre of mass. Plane z = 0, gravity -g z.
* State y = (gamma, w): gamma = the world's up vector in body axes,
  w = the angular velocity in body axes. Rolling makes the rest (position,
  heading) ignorable: the spin about the vertical is w . gamma.
* The contact point is where the surface's outward normal is -gamma:
  minimising gamma . x over (x - c_e)^T E^-2 (x - c_e) = 1 gives
  x_P = c_e - E^2 gamma / sqrt(gamma^T E^2 gamma). r = -x_P points from the
  contact to the centre of mass; the centre of mass is gamma . r above
  the plane.
* Kinematics: d gamma/dt = gamma x w (a fixed vector seen from the body).
  dr/dt follows from differentiating x_P(gamma) (sigma = sqrt(gamma^T E^2
  gamma), d sigma/dt = gamma^T E^2 gamma' / sigma):
      dr/dt = (E^2 gamma' sigma - E^2 gamma sigma') / sigma^2
* Rolling: the centre of mass moves with v = w x r (body components), so
  its acceleration is a = w' x r + w x r' + w x (w x r) (the last from the
  body frame's rotation: d/dt|world v = dv/dt|body + w x v, and
  dv/dt|body = w' x r + w x r').
* Newton: F = m a + m g gamma (F the contact force). Euler about the centre
  of mass: I w' + w x I w = (-r) x F. Eliminating F:
      [I + m (|r|^2 1 - r r^T)] w' = -w x I w
                                    - m r x (w x r' + w x (w x r) + g gamma)
  one 3x3 solve per evaluation.
* Integrated with scipy's DOP853 at rtol 1e-13 (atol 1e-16); the spin's
  sign change w . gamma = 0 located by solve_ivp's event root finder.
* Linear modes: the same right-hand side linearised about steady spinning
  upright (gamma = z, w = (0, 0, spin); an equilibrium), its Jacobian by
  complex-step differentiation (exact to rounding), eigenvalues
  sigma +- i omega by numpy. Without spin they are the roll and pitch
  frequencies; spinning, one pair grows (sigma > 0) and one decays.
* Output rows: rattleback.csv, for each run (spin sense), its first
  reversal time and the state there; rattleback_modes.csv, for spin 0 and
  +-5 rad/s each oscillatory mode (omega > 0): sigma, omega and the
  eigenvector's gamma_x, gamma_y, w_x, w_y (real and imaginary parts,
  scaled so that the larger |gamma| component is 1). Checks printed: the same runs at rtol 1e-11 (the times'
  change), the energy drift
      E = 1/2 m |w x r|^2 + 1/2 w . I w + m g gamma . r
  and |gamma| - 1.
"""

import csv
import os

import numpy as np
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

M, G = 1.0, 9.81
SEMI = np.array([0.20, 0.03, 0.02])
E2 = SEMI**2
CENTRE = np.array([0.0, 0.0, 0.01])
INERTIA = np.array([[2e-4, 2e-5, 0.0], [2e-5, 16e-4, 0.0], [0.0, 0.0, 17e-4]])
TILT = 1e-3
RUNS = {"counterclockwise": (5.0, 8.0), "clockwise": (-5.0, 25.0)}


def contact_to_com(gamma):
    sigma = np.sqrt(gamma @ (E2 * gamma))
    return -(CENTRE - E2 * gamma / sigma), sigma


def rhs(_t, y):
    gamma, w = y[:3], y[3:]
    r, sigma = contact_to_com(gamma)
    dgamma = np.cross(gamma, w)
    dsigma = gamma @ (E2 * dgamma) / sigma
    dr = (E2 * dgamma * sigma - E2 * gamma * dsigma) / sigma**2
    inertia_p = INERTIA + M * (r @ r * np.eye(3) - np.outer(r, r))
    rhs_w = -np.cross(w, INERTIA @ w) - M * np.cross(
        r, np.cross(w, dr) + np.cross(w, np.cross(w, r)) + G * gamma
    )
    return np.concatenate([dgamma, np.linalg.solve(inertia_p, rhs_w)])


def energy(y):
    gamma, w = y[:3], y[3:]
    r, _ = contact_to_com(gamma)
    v = np.cross(w, r)
    return 0.5 * M * v @ v + 0.5 * w @ INERTIA @ w + M * G * gamma @ r


def start(spin):
    # Tilted by the rotation vector (TILT, TILT, 0), spinning about the vertical.
    a = Rotation.from_rotvec([TILT, TILT, 0.0]).as_matrix()
    gamma = a.T @ np.array([0.0, 0.0, 1.0])
    w = a.T @ np.array([0.0, 0.0, spin])
    return np.concatenate([gamma, w])


def spin_event(_t, y):
    return y[:3] @ y[3:]


spin_event.terminal = True


def run(spin, duration, rtol):
    y0 = start(spin)
    sol = solve_ivp(
        rhs,
        (0.0, duration),
        y0,
        method="DOP853",
        rtol=rtol,
        atol=1e-16,
        events=spin_event,
        dense_output=True,
    )
    assert sol.status == 1, f"no reversal in {duration} s ({sol.message})"
    t = sol.t_events[0][0]
    ts = np.linspace(0.0, t, 2001)
    e0 = energy(y0)
    drift = max(abs(energy(sol.sol(s)) / e0 - 1.0) for s in ts)
    norm = max(abs(np.linalg.norm(sol.sol(s)[:3]) - 1.0) for s in ts)
    return t, sol.y_events[0][0], drift, norm


def modes(spin):
    y0 = np.array([0.0, 0.0, 1.0, 0.0, 0.0, spin])
    jac = np.zeros((6, 6))
    for k in range(6):
        step = np.zeros(6, dtype=complex)
        step[k] = 1e-30j
        jac[:, k] = rhs(0.0, y0 + step).imag / 1e-30
    assert np.abs(rhs(0.0, y0)).max() == 0.0, "not an equilibrium"
    values, vectors = np.linalg.eig(jac)
    out = []
    for i in np.argsort(values.imag):
        if values[i].imag > 1.0:
            v = vectors[:, i]
            v = v / v[np.argmax(np.abs(v[:2]))]
            out.append((values[i], v))
    return out


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact")
    rows = []
    for name, (spin, duration) in RUNS.items():
        t, y, drift, norm = run(spin, duration, 1e-13)
        t_loose, _, _, _ = run(spin, duration, 1e-11)
        print(
            f"{name}: spin {spin} rad/s, first reversal at {t:.12f} s "
            f"(rtol 1e-11: {t_loose - t:+.2e} s); |dE/E| {drift:.1e}, "
            f"||gamma|-1| {norm:.1e}"
        )
        rows.append([name, spin, TILT, repr(float(t))] + [repr(float(v)) for v in y])
    path = os.path.join(out, "rattleback.csv")
    with open(path, "w", newline="") as fh:
        fh.write("# tests/data/gen/rattleback.py: Kane & Levinson's rattleback rolling, "
                 "first spin reversal (DOP853, rtol 1e-13)\n")
        w = csv.writer(fh)
        w.writerow(["run", "spin", "tilt", "t", "gx", "gy", "gz", "wx", "wy", "wz"])
        w.writerows(rows)
    print(f"wrote {os.path.normpath(path)}")
    path = os.path.join(out, "rattleback_modes.csv")
    with open(path, "w", newline="") as fh:
        fh.write("# tests/data/gen/rattleback.py: linear modes about steady spinning "
                 "upright (complex-step Jacobian, numpy eig)\n")
        w = csv.writer(fh)
        w.writerow(["spin", "sigma", "omega", "gx_re", "gx_im", "gy_re", "gy_im",
                    "wx_re", "wx_im", "wy_re", "wy_im"])
        for spin in [0.0, 5.0, -5.0]:
            for value, v in modes(spin):
                print(f"spin {spin:+.0f}: sigma {value.real:+.12e} /s, omega {value.imag:.12f} rad/s")
                parts = [v[0], v[1], v[3], v[4]]
                w.writerow([spin, repr(float(value.real)), repr(float(value.imag))]
                           + [repr(float(x)) for p in parts for x in (p.real, p.imag)])
    print(f"wrote {os.path.normpath(path)}")


if __name__ == "__main__":
    main()
