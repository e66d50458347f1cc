#!/usr/bin/env python3
"""Along-track position error after a GNSS outage: the bound of any IMU + RTK estimator.

A straight row at constant heading, the along-track axis only (field_realism/README, "Session
tractor5"). States: position p, velocity v, the forward specific-force error eps = g*dtheta + db_x
(pitch error and forward accelerometer bias: on one row only their sum acts), and the receiver's
correlated error e (first-order Gauss-Markov). eps random-walks with g x the gyro's angle random
walk (the pitch follows the y gyro's white noise); v takes the accelerometer's velocity random walk.
The fixes measure p + e at 10 Hz (plus a white part), optionally the velocity. The Kalman filter's
steady state before the outage, propagated through it, gives the along-track sigma at its end:
what the best estimator with exactly these models reaches (a vehicle model is not included).

Usage: python3 outage_along_track_bound.py [ARW_rad_per_rts ...]
"""
import sys

import numpy as np

G_MPS2 = 9.81
DT_S = 0.1  # the fixes' interval (10 Hz RTK)


def bound(arw_radps_rthz, outage_s=10.0, gnss_gm_std_m=0.008, gnss_gm_tau_s=30.0,
          gnss_white_std_m=0.005, gnss_vel_std_mps=None, vrw_mps_rts=0.012 / 60):
    """Returns (eps sigma at the outage's start m/s^2, velocity sigma m/s, p sigma at the end m)."""
    phi = np.eye(4)
    phi[0, 1], phi[0, 2], phi[1, 2] = DT_S, DT_S**2 / 2, DT_S
    phi[3, 3] = np.exp(-DT_S / gnss_gm_tau_s)
    dt = DT_S
    q_jerk = (G_MPS2 * arw_radps_rthz) ** 2
    q = np.zeros((4, 4))
    q[:3, :3] = q_jerk * np.array([[dt**5 / 20, dt**4 / 8, dt**3 / 6],
                                   [dt**4 / 8, dt**3 / 3, dt**2 / 2],
                                   [dt**3 / 6, dt**2 / 2, dt]])
    q[:2, :2] += vrw_mps_rts**2 * np.array([[dt**3 / 3, dt**2 / 2], [dt**2 / 2, dt]])
    q[3, 3] = gnss_gm_std_m**2 * (1 - phi[3, 3] ** 2)
    rows, noise = [[1, 0, 0, 1.0]], [gnss_white_std_m**2]
    if gnss_vel_std_mps:
        rows.append([0, 1, 0, 0.0])
        noise.append(gnss_vel_std_mps**2)
    h, r = np.array(rows), np.diag(noise)
    p = np.diag([1.0, 1.0, 1e-4, gnss_gm_std_m**2])
    for _ in range(20000):  # to the steady state
        p = phi @ p @ phi.T + q
        k = p @ h.T @ np.linalg.inv(h @ p @ h.T + r)
        p = (np.eye(4) - k @ h) @ p
    eps_std, vel_std = np.sqrt(p[2, 2]), np.sqrt(p[1, 1])
    for _ in range(int(round(outage_s / DT_S))):
        p = phi @ p @ phi.T + q
    return eps_std, vel_std, np.sqrt(p[0, 0])


def main():
    arws = [float(a) for a in sys.argv[1:]] or [4.4e-5, 7.5e-5]
    for arw in arws:
        for vel in (None, 0.01):
            eps, v, pos = bound(arw, gnss_vel_std_mps=vel)
            aid = "positions" if vel is None else "positions + 1 cm/s velocity"
            print(f"ARW {arw:.2e} rad/rt-s, {aid}: eps {eps * 1e3:.2f} mm/s^2, "
                  f"v {v * 100:.2f} cm/s at the start; along-track sigma after 10 s "
                  f"{pos * 100:.1f} cm (gyro noise in the gap alone "
                  f"{G_MPS2 * arw * 10**2.5 / np.sqrt(20) * 100:.1f} cm)")


if __name__ == "__main__":
    main()
