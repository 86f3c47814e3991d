"""Sedov-Taylor point-blast similarity solution (standard case).

Follows the procedure of J. R. Kamm and F. X. Timmes, "On efficient generation
of numerically robust Sedov solutions", LA-UR-07-2849 (2007), itself built on
J. R. Kamm, "Evaluation of the Sedov-von Neumann-Taylor blast wave solution",
LA-UR-00-6055 (2000), and Sedov's parametric closed form:

* ambient gas at rest, uniform density rho0 (omega = 0), zero pressure;
* energy E released at the origin at t = 0; geometry j = 1, 2, 3 (planar,
  cylindrical, spherical; the validated and default case is j = 3);
* the "standard" case of Kamm & Timmes (1 < gamma, gamma != 2, and for j = 3
  gamma < 7); the singular and vacuum cases are refused.

Similarity variables (j2w = j + 2):
    lambda = r / r2(t)      shock at lambda = 1, r2 = (E t^2 / (alpha rho0))^(1/j2w)
    V      = v t / r        runs from V0 = 2/(j2w gamma) (centre) to
                            V2 = 4/(j2w (gamma+1)) (shock)
With
    x1 = a V,  x2 = b (c V - 1),  x3 = d (1 - e V),  x4 = b (1 - c V / gamma)
    a = j2w (gamma+1)/4, b = (gamma+1)/(gamma-1), c = j2w gamma/2,
    d = j2w (gamma+1) / (j2w (gamma+1) - 2 (2 + j (gamma-1))), e = (2 + j (gamma-1))/2
the solution behind the shock is, in closed form,
    lambda = x1^-a0 x2^-a2 x3^-a1
    f = v/v2     = x1 lambda
    g = rho/rho2 = x2^a3 x3^a4 x4^a5
    h = p/p2     = x1^(a0 j) x3^(a4 - 2 a1) x4^(1 + a5)
with exponents
    a0 = 2/j2w,  a2 = (1-gamma)/(2(gamma-1) + j),
    a1 = j2w gamma/(2 + j(gamma-1)) * (2 j (2-gamma)/(gamma j2w^2) - a2),
    a3 = j/(2(gamma-1) + j),  a4 = j2w a1/(2-gamma),  a5 = -2/(2-gamma)
and the strong-shock (Rankine-Hugoniot) values just behind the shock
    rho2 = b rho0,  v2 = 2 u_s/(gamma+1),  p2 = 2 rho0 u_s^2/(gamma+1),
    u_s = dr2/dt = a0 r2 / t.

Energy: E = sigma_j int_0^r2 (rho v^2/2 + p/(gamma-1)) r^(j-1) dr with
sigma_j = 1, 2 pi, 4 pi, which gives E = alpha rho0 r2^j2w / t^2 with
    alpha = sigma_j a0^2 int_0^1 [ b/2 (2/(gamma+1))^2 g f^2
                                  + 2/((gamma+1)(gamma-1)) h ] lambda^(j-1) dlambda,
so that r2 = xi0 (E t^2/rho0)^(1/j2w) with xi0 = alpha^(-1/j2w)
(1.15167 for j = 3, gamma = 5/3).

Numerical robustness (the point of Kamm & Timmes): near the centre lambda
varies as a large power of (V - V0) (for j = 3, gamma = 5/3,
V - V0 ~ lambda^6.5), so V itself cannot resolve small radii in double
precision.  Here everything is parametrised by delta = V - V0 (x2 = b c delta
exactly), and lambda(delta) is inverted by bisection in log(delta), so the
profile is accurate down to lambda ~ 1e-40.  The energy integral is done in
s = log(delta) with adaptive quadrature.
"""

import math

import numpy as np
from scipy import integrate

__all__ = ["SedovSolution", "sedov_profile", "shock_radius", "shock_constant",
           "post_shock_state"]

# Smallest delta = V - V0 used: lambda there is below 1e-40 for the cases
# supported, so anything closer to the centre is the centre.
_LOG_DELTA_MIN = math.log(1e-300)
_BISECTION_STEPS = 80


class SedovSolution:
    """The dimensionless Sedov solution for one (gamma, j); cache and reuse it."""

    def __init__(self, gamma=5.0 / 3.0, j=3):
        gamma = float(gamma)
        if j not in (1, 2, 3):
            raise ValueError("j must be 1, 2 or 3")
        if not gamma > 1.0:
            raise ValueError("gamma must be > 1")
        if abs(gamma - 2.0) < 1e-9:
            raise ValueError("gamma = 2 is a singular Sedov case (not implemented)")
        j2w = j + 2.0
        d_den = j2w * (gamma + 1.0) - 2.0 * (2.0 + j * (gamma - 1.0))
        if d_den <= 0.0:
            raise ValueError("gamma too large: vacuum/singular Sedov case (not implemented)")
        self.gamma, self.j, self.j2w = gamma, j, j2w
        self.a = j2w * (gamma + 1.0) / 4.0
        self.b = (gamma + 1.0) / (gamma - 1.0)
        self.c = j2w * gamma / 2.0
        self.d = j2w * (gamma + 1.0) / d_den
        self.e = (2.0 + j * (gamma - 1.0)) / 2.0
        self.a0 = 2.0 / j2w
        self.a2 = (1.0 - gamma) / (2.0 * (gamma - 1.0) + j)
        self.a1 = (j2w * gamma / (2.0 + j * (gamma - 1.0))
                   * (2.0 * j * (2.0 - gamma) / (gamma * j2w ** 2) - self.a2))
        self.a3 = j / (2.0 * (gamma - 1.0) + j)
        self.a4 = j2w * self.a1 / (2.0 - gamma)
        self.a5 = -2.0 / (2.0 - gamma)
        self.V0 = 2.0 / (j2w * gamma)
        self.V2 = 4.0 / (j2w * (gamma + 1.0))
        self.log_delta_max = math.log(self.V2 - self.V0)
        self.sigma = {1: 1.0, 2: 2.0 * math.pi, 3: 4.0 * math.pi}[j]
        self.alpha = self._energy_integral()
        self.xi0 = self.alpha ** (-1.0 / j2w)

    # -- the closed form, parametrised by s = log(V - V0) ----------------------
    def _logs(self, s):
        """log x1..x4 at s = log(delta)."""
        delta = np.exp(s)
        V = self.V0 + delta
        lx1 = np.log(self.a * V)
        lx2 = math.log(self.b * self.c) + s
        lx3 = np.log(self.d * (1.0 - self.e * V))
        lx4 = np.log(self.b * (1.0 - self.c * V / self.gamma))
        return V, delta, lx1, lx2, lx3, lx4

    def _log_lambda(self, s):
        _, _, lx1, lx2, lx3, _ = self._logs(s)
        return -self.a0 * lx1 - self.a2 * lx2 - self.a1 * lx3

    def similarity(self, s):
        """lambda, f, g, h and dlambda/ds at s = log(V - V0) (arrays)."""
        V, delta, lx1, lx2, lx3, lx4 = self._logs(np.asarray(s, dtype=float))
        lam = np.exp(-self.a0 * lx1 - self.a2 * lx2 - self.a1 * lx3)
        f = np.exp(lx1) * lam
        g = np.exp(self.a3 * lx2 + self.a4 * lx3 + self.a5 * lx4)
        h = np.exp(self.a0 * self.j * lx1 + (self.a4 - 2.0 * self.a1) * lx3
                   + (1.0 + self.a5) * lx4)
        # dln(lambda)/dV = -a0 a/x1 - a2 b c/x2 + a1 d e/x3; x2 = b c delta.
        dlnlam_dV = (-self.a0 / V - self.a2 / delta
                     + self.a1 * self.d * self.e / np.exp(lx3))
        dlam_ds = lam * dlnlam_dV * delta
        return lam, f, g, h, dlam_ds

    def _energy_integral(self):
        gm = self.gamma
        kin = 0.5 * self.b * (2.0 / (gm + 1.0)) ** 2
        thm = 2.0 / ((gm + 1.0) * (gm - 1.0))

        def integrand(s):
            lam, f, g, h, dlam = self.similarity(s)
            return float((kin * g * f * f + thm * h) * lam ** (self.j - 1) * dlam)

        lo = math.log(1e-80)
        hi = self.log_delta_max
        # Most of the integral lies near the shock (s near hi); split there.
        mid = hi - 10.0
        total = 0.0
        for a, b in ((lo, mid), (mid, hi)):
            val, _ = integrate.quad(integrand, a, b, epsabs=0.0, epsrel=1e-13, limit=500)
            total += val
        return self.sigma * self.a0 ** 2 * total

    # -- inversion lambda -> s ---------------------------------------------------
    def solve_s(self, lam):
        """s = log(V - V0) with lambda(s) = lam, for 0 <= lam <= 1 (vectorised bisection)."""
        lam = np.asarray(lam, dtype=float)
        target = np.log(np.maximum(lam, 1e-300))
        lo = np.full(lam.shape, _LOG_DELTA_MIN)
        hi = np.full(lam.shape, self.log_delta_max)
        for _ in range(_BISECTION_STEPS):
            mid = 0.5 * (lo + hi)
            below = self._log_lambda(mid) < target
            lo = np.where(below, mid, lo)
            hi = np.where(below, hi, mid)
        s = 0.5 * (lo + hi)
        s = np.where(lam >= 1.0, self.log_delta_max, s)
        return s

    # -- dimensional quantities ---------------------------------------------------
    def shock_radius(self, t, E=1.0, rho0=1.0):
        return self.xi0 * (E * t * t / rho0) ** (1.0 / self.j2w)

    def post_shock_state(self, t, E=1.0, rho0=1.0):
        """(rho2, p2, v2, r2, u_s) just behind the shock at time t."""
        r2 = self.shock_radius(t, E, rho0)
        us = self.a0 * r2 / t
        gm = self.gamma
        return self.b * rho0, 2.0 * rho0 * us * us / (gm + 1.0), 2.0 * us / (gm + 1.0), r2, us

    def profile(self, r, t, E=1.0, rho0=1.0):
        if not t > 0.0:
            raise ValueError("time must be > 0")
        r = np.abs(np.asarray(r, dtype=float))
        rho2, p2, v2, r2, _ = self.post_shock_state(t, E, rho0)
        rho = np.full(r.shape, float(rho0))
        p = np.zeros(r.shape)
        v = np.zeros(r.shape)
        inside = r <= r2
        if np.any(inside):
            lam = r[inside] / r2
            s = self.solve_s(lam)
            _, f, g, h, _ = self.similarity(s)
            rho[inside] = rho2 * g
            p[inside] = p2 * h
            v[inside] = v2 * f
        return rho, p, v


_cache = {}


def _solution(gamma, j=3):
    key = (float(gamma), int(j))
    if key not in _cache:
        _cache[key] = SedovSolution(gamma, j)
    return _cache[key]


def shock_constant(gamma=5.0 / 3.0, j=3):
    """xi0 in r2 = xi0 (E t^2/rho0)^(1/(j+2)); 1.15167 for gamma = 5/3, j = 3."""
    return _solution(gamma, j).xi0


def shock_radius(t, E=1.0, rho0=1.0, gamma=5.0 / 3.0, j=3):
    """Shock radius r2(t) = xi0 (E t^2/rho0)^(1/(j+2))."""
    return _solution(gamma, j).shock_radius(t, E, rho0)


def post_shock_state(t, E=1.0, rho0=1.0, gamma=5.0 / 3.0, j=3):
    """(density, pressure, velocity, shock radius, shock speed) just behind the shock."""
    return _solution(gamma, j).post_shock_state(t, E, rho0)


def sedov_profile(r, t, E=1.0, rho0=1.0, gamma=5.0 / 3.0, j=3):
    """(density, pressure, radial velocity) arrays at radii r and time t > 0.

    Outside the shock: rho0, 0, 0.  Inside: the similarity solution.
    """
    return _solution(gamma, j).profile(r, t, E, rho0)


if __name__ == "__main__":
    sol = _solution(5.0 / 3.0, 3)
    print("gamma=5/3 j=3: alpha=%.10f xi0=%.10f" % (sol.alpha, sol.xi0))
    print("post-shock state at t=1:", post_shock_state(1.0))
