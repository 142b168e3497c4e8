"""A rectangular tank swayed as X(t) = A0 (cos(2 pi t/T) - 1) from rest (the
ULPH-NOSBPD paper's eq. 60), shared by the validation scripts of the
sloshing tutorials: the tank's motion, the linear modal solution of the
free-surface elevation, and the elevation a run gives at a probe that
moves with the tank.

    from swayTank import SwayTank
    tank = SwayTank(length=1.73, depth=0.5, amplitude=0.032, period=1.875)
    tank.linear_eta(t, x)          # [m], x from the left wall
    tank.probe_elevation(case, dx, x)

The linear solution: in the tank's frame the modes are cos(k_n x),
k_n = n pi/L, w_n^2 = g k_n tanh(k_n h); projecting the free-surface
conditions on them gives
    eta(x, t) = sum_{n odd} beta_n(t) cos(k_n x),
    beta_n'' + w_n^2 beta_n = (4 tanh(k_n h)/(L k_n)) X''(t),
which from rest is
    beta_n = F_n/(w_n^2 - w^2) (cos w t - cos w_n t),
    F_n = -(4 tanh(k_n h)/(L k_n)) A0 w^2,
summed here over n < 200.
"""
import math

from foamCloud import read_positions, times


class SwayTank:
    def __init__(self, length, depth, amplitude, period, g=9.81):
        self.L, self.h, self.A0, self.T, self.g = \
            length, depth, amplitude, period, g
        self.w = 2 * math.pi / period

    def tank_x(self, t):
        """The tank's displacement [m]"""
        return self.A0 * (math.cos(self.w * t) - 1)

    def linear_eta(self, t, x):
        """Linear elevation [m] at x from the left wall (tank's frame)"""
        s = 0.0
        for n in range(1, 200, 2):
            k = n * math.pi / self.L
            th = math.tanh(k * self.h)
            wn = math.sqrt(self.g * k * th)
            F = -(4 * th / (self.L * k)) * self.A0 * self.w * self.w
            s += F / (wn * wn - self.w * self.w) \
                * (math.cos(self.w * t) - math.cos(wn * t)) * math.cos(k * x)
        return s

    def probe_elevation(self, case, dx, x, body="water"):
        """(t, eta) at every written time: the highest particle of the body
        within 1.5 spacings of the probe x (moving with the tank) plus half
        a spacing, less the depth"""
        out = []
        for t, name in times(case):
            xp = x + self.tank_x(t)
            near = [p[1] for p in read_positions(case, name, body)
                    if abs(p[0] - xp) < 1.5 * dx]
            if near:
                out.append((t, max(near) + 0.5 * dx - self.h))
        return out

