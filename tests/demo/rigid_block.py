"""Newmark's rigid sliding block (Newmark 1965, "Effects of earthquakes on
dams and embankments", Geotechnique 15(2)) under the rectangular pulse of
tests/data/pulse_0.2s.txt, integrated exactly enough (dt = 1e-7 s) for the
demo checks of joint contact."""


def rigid_slip(peak_g, mu=0.2, g=9.81, dt=1e-7):
    """Slip of a rigid block (friction mu) on a base accelerating as the
    record: 0 at t = 0, A from 1 ms to 0.2 s, 0 from 0.201 s, linear in
    between; the block slides back while A > mu g and until it stops."""
    A = peak_g * g

    def ag(t):
        if t < 0.001:
            return A * t / 0.001
        if t <= 0.2:
            return A
        if t < 0.201:
            return A * (0.201 - t) / 0.001
        return 0.0

    v = x = t = 0.0
    while t < 2.0:
        a = mu * g - ag(t)  # relative acceleration while sliding back
        if v >= 0.0 and a >= 0.0:
            if t > 0.002:
                break  # stopped
            a = 0.0  # not yet sliding
        v += a * dt
        x += v * dt
        t += dt
    return -x
