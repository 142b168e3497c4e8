"""Checks shared by the case tests of the swayed (sloshing) tanks: the tank
is where its motion X(t) = A0 (cos(2 pi t/T) - 1) (the ULPH-NOSBPD paper's
eq. 60) puts it, and the water stays inside the moving tank.

    from swayChecks import check_sway   # after etc/python is on the path
    check_sway(t, case, SwayTank(...), height=1.15)
    check_tank(t, case, SwayTank(...))  # the tank's position only
"""
from foamCloud import read_positions, times


def check_tank(t, case, tank, walls="tank"):
    """The tank where its motion puts it half a period in, where it is
    furthest from its start"""
    th, half = min(times(case), key=lambda tn: abs(tn[0] - tank.T / 2))
    X = tank.tank_x(th)
    w0 = read_positions(case, "0", walls)
    w1 = read_positions(case, half, walls)
    err = max(abs(b[0] - a[0] - X) + abs(b[1] - a[1])
              for a, b in zip(w0, w1))
    t.check("tank where X = A0 (cos wt - 1) puts it at t = %g s, X = %.4f m"
            " (error %.1e m)" % (th, X, err), err < 1e-6 and X < -0.06)


def check_sway(t, case, tank, height, walls="tank", fluid="water"):
    check_tank(t, case, tank, walls)
    last = times(case)[-1][1]
    X = tank.tank_x(float(last))
    water = read_positions(case, last, fluid)
    inside = all(X <= p[0] <= tank.L + X and 0 <= p[1] <= height
                 for p in water)
    t.check("water inside the moving tank", inside)
