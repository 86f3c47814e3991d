"""Noh implosion (W. F. Noh, J. Comput. Phys. 72 (1987) 78), exact solution.

Cold gas (p = 0) of uniform density rho0 moves radially inward at speed u0
towards the origin from t = 0.  An infinitely strong shock stands off the
origin and moves outward at constant speed; behind it the gas is at rest.
For geometry j (3 = spherical, the default; 2 = cylindrical; 1 = planar):

    shock:        r_s = u_s t,   u_s = (gamma - 1) u0 / 2
    r <  r_s:     rho = rho0 ((gamma + 1)/(gamma - 1))^j
                  v   = 0
                  p   = (gamma - 1)/2 * rho u0^2   (all kinetic energy -> heat)
    r >= r_s:     rho = rho0 (1 + u0 t / r)^(j - 1)
                  v   = -u0
                  p   = 0

For gamma = 5/3, rho0 = 1, u0 = 1, j = 3: r_s = t/3, rho = 64, p = 64/3
inside; 16 rho0 just ahead of the shock.
"""

import numpy as np

__all__ = ["noh_profile", "shock_radius", "post_shock_state"]


def _check(gamma, t):
    if not gamma > 1.0:
        raise ValueError("gamma must be > 1")
    if not t > 0.0:
        raise ValueError("time must be > 0")


def shock_radius(t, rho0=1.0, gamma=5.0 / 3.0, u0=1.0, j=3):
    """r_s = (gamma - 1) u0 t / 2."""
    _check(gamma, t)
    return 0.5 * (gamma - 1.0) * u0 * t


def post_shock_state(t=1.0, rho0=1.0, gamma=5.0 / 3.0, u0=1.0, j=3):
    """(density, pressure, velocity, shock radius, pre-shock density at the shock)."""
    _check(gamma, t)
    rho2 = rho0 * ((gamma + 1.0) / (gamma - 1.0)) ** j
    p2 = 0.5 * (gamma - 1.0) * rho2 * u0 * u0
    rs = shock_radius(t, rho0, gamma, u0, j)
    rho1 = rho0 * (1.0 + u0 * t / rs) ** (j - 1)
    return rho2, p2, 0.0, rs, rho1


def noh_profile(r, t, rho0=1.0, gamma=5.0 / 3.0, u0=1.0, j=3):
    """(density, pressure, radial velocity) arrays at radii r and time t > 0."""
    _check(gamma, t)
    r = np.abs(np.asarray(r, dtype=float))
    rho2, p2, _, rs, _ = post_shock_state(t, rho0, gamma, u0, j)
    inside = r < rs
    with np.errstate(divide="ignore"):
        ahead = rho0 * (1.0 + u0 * t / np.where(inside, 1.0, r)) ** (j - 1)
    rho = np.where(inside, rho2, ahead)
    p = np.where(inside, p2, 0.0)
    v = np.where(inside, 0.0, -float(u0))
    return rho, p, v


if __name__ == "__main__":
    print("t=1: shock radius %.6g, post-shock (rho, p, v, r_s, rho_ahead) =" % shock_radius(1.0),
          post_shock_state(1.0))
