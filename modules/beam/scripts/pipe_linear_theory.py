#!/usr/bin/python3
"""Independent reference for the pipe verification: the linear Euler-Bernoulli plug-flow equation
(Paidoussis, Fluid-Structure Interactions vol. 1, eq. 3.71 without gravity, tension, damping)

    eta'''' + u^2 eta'' + 2 sqrt(beta) u eta_dot' + eta_ddot = 0,   xi in [0, 1], tau = t sqrt(EI/(m+M))/L^2

solved by Chebyshev collocation (not by the fowtsim code). `coriolis` scales the 2 sqrt(beta) u term:
1 is the classical equation, 0.5 keeps half of it (the momentum flux of the seed's eq. 3.17 carries
only the fluid's velocity relative to the pipe, which drops one of the two Coriolis halves).
Prints the cantilever frequencies of seed Table 3.1 (flow half), the cantilever flutter threshold
for beta = 0.2 and the divergence thresholds of pinned-pinned and clamped-clamped pipes."""
import numpy as np
import scipy.linalg as sla


def cheb(n):
    x = np.cos(np.pi * np.arange(n + 1) / n)
    c = np.hstack([2, np.ones(n - 1), 2]) * (-1) ** np.arange(n + 1)
    dx = x[:, None] - x[None, :]
    d = np.outer(c, 1 / c) / (dx + np.eye(n + 1))
    d -= np.diag(d.sum(axis=1))
    return x, d


def eigenvalues(u, beta, ends, n=60, coriolis=1.0):
    x, d = cheb(n)
    d1 = -2.0 * d  # xi = (1 - x)/2: xi = 0 at x = 1 (first point), xi = 1 at x = -1 (last point)
    d2, d3, d4 = d1 @ d1, d1 @ d1 @ d1, d1 @ d1 @ d1 @ d1
    eye = np.eye(n + 1)
    k = d4 + u * u * d2
    c = 2.0 * coriolis * np.sqrt(beta) * u * d1
    m = eye.copy()
    root, tip = 0, n
    rows = {"clamped-free": [(root, eye), (root, d1), (tip, d2), (tip, d3)],
            "pinned-pinned": [(root, eye), (root, d2), (tip, eye), (tip, d2)],
            "clamped-clamped": [(root, eye), (root, d1), (tip, eye), (tip, d1)]}[ends]
    # Boundary conditions replace the equation at the two points next to each end.
    replaced = [root, root + 1, tip, tip - 1]
    for (point, op), r in zip(rows, replaced):
        k[r] = op[point]
        c[r] = 0.0
        m[r] = 0.0
    size = n + 1
    a = np.block([[np.zeros((size, size)), np.eye(size)], [-k, -c]])
    b = np.block([[np.eye(size), np.zeros((size, size))], [np.zeros((size, size)), m]])
    lam = sla.eig(a, b, right=False)
    return lam[np.isfinite(lam) & (np.abs(lam) < 1e6)]


def rotating_frequencies(mu_omega, in_plane, n=60, count=3):
    """Rotating cantilever (hub radius 0), Euler-Bernoulli, inextensible:
    eta'''' - (T eta')' - s eta + eta_ddot = 0 with the centrifugal tension T = mu^2 (1 - xi^2)/2
    and s = mu^2 in the plane of rotation (lead-lag), 0 out of it (flap)."""
    x, d = cheb(n)
    d1 = -2.0 * d
    xi = (1.0 - x) / 2.0
    d2, d3, d4 = d1 @ d1, d1 @ d1 @ d1, d1 @ d1 @ d1 @ d1
    eye = np.eye(n + 1)
    tension = mu_omega ** 2 * (1.0 - xi ** 2) / 2.0
    k = d4 - np.diag(tension) @ d2 + np.diag(mu_omega ** 2 * xi) @ d1  # -(T eta')' = -T eta'' - T' eta'
    if in_plane:
        k -= mu_omega ** 2 * eye
    m = eye.copy()
    for (point, op), r in zip([(0, eye), (0, d1), (n, d2), (n, d3)], [0, 1, n, n - 1]):
        k[r] = op[point]
        m[r] = 0.0
    lam = sla.eig(k, m, right=False)
    lam = np.sort(np.sqrt(lam[np.isfinite(lam) & (lam.real > 0)].real))
    return lam[:count]


def timoshenko_frequencies(u, mu_a, mu_m, n=50, count=3, bore_ratio=0.8, poisson=0.3, wall_density=1000.0):
    """The same cantilever as a Timoshenko beam (shear k G A^p with k = 1, rotary inertia of wall
    and fluid), the flow as in the plug-flow equation: with xi, tau as above,
        kappa (w'' - psi') - u^2 w'' - 2 sqrt(beta) u w_dot' - w_ddot = 0,
        psi'' + kappa (w' - psi) - r psi_ddot = 0,
    kappa = k G A^p L^2/EI, r = (rho^p I + rho^f I^f)/((m^p + m^f) L^2); the pipe of
    pipe_benchmarks::cantilever (L = 1, D = 0.8 D_o, nu = 0.3, wall 1000 kg/m^3)."""
    r2 = bore_ratio ** 2
    do2 = 16.0 / (mu_a * (1.0 + r2))
    fluid_density = mu_m * (1.0 - r2) * wall_density / (r2 * (1.0 - mu_m)) if mu_m < 1 else 0.0
    area, second = np.pi / 4 * do2 * (1 - r2), np.pi / 64 * do2 ** 2 * (1 - r2 ** 2)
    mass = wall_density * area + fluid_density * np.pi / 4 * do2 * r2
    rotary = (wall_density * second + fluid_density * np.pi / 64 * do2 ** 2 * r2 ** 2) / mass
    kappa = mu_a / (2.0 * (1.0 + poisson))
    beta = mu_m
    x, d = cheb(n)
    d1 = -2.0 * d
    d2 = d1 @ d1
    eye, zero = np.eye(n + 1), np.zeros((n + 1, n + 1))
    k = np.block([[-(kappa - u * u) * d2, kappa * d1], [-kappa * d1, -d2 + kappa * eye]])
    c = np.block([[2.0 * np.sqrt(beta) * u * d1, zero], [zero, zero]])
    m = np.block([[eye, zero], [zero, rotary * eye]])
    w, p = 0, n + 1  # offsets of the w and psi blocks
    bcs = [(w + 0, np.hstack([eye[0], 0 * eye[0]])),                    # w(0) = 0
           (w + n, np.hstack([d1[n], -eye[n]])),                        # w'(1) - psi(1) = 0
           (p + 0, np.hstack([0 * eye[0], eye[0]])),                    # psi(0) = 0
           (p + n, np.hstack([0 * eye[0], d1[n]]))]                     # psi'(1) = 0
    for row, op in bcs:
        k[row] = op
        c[row] = 0.0
        m[row] = 0.0
    size = 2 * (n + 1)
    a = np.block([[np.zeros((size, size)), np.eye(size)], [-k, -c]])
    b = np.block([[np.eye(size), np.zeros((size, size))], [np.zeros((size, size)), m]])
    lam = sla.eig(a, b, right=False)
    lam = lam[np.isfinite(lam) & (lam.imag > 1e-9) & (np.abs(lam) < 1e5)]
    return np.sort(lam.imag)[:count]


def frequencies(u, beta, ends, count=3, coriolis=1.0):
    lam = eigenvalues(u, beta, ends, coriolis=coriolis)
    lam = lam[lam.imag > 1e-9]
    lam = lam[np.argsort(lam.imag)]
    return lam[:count]


def flutter_threshold(beta, lo, hi, coriolis=1.0):
    def growth(u):
        lam = eigenvalues(u, beta, "clamped-free", coriolis=coriolis)
        return np.max(lam[np.abs(lam) < 1e3].real)  # the lowest modes (Paidoussis Fig. 3.27 shows four)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if growth(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def divergence_threshold(ends, lo, hi):
    def lowest(u):
        lam = eigenvalues(u, 0.0, ends)
        return np.min(np.abs(lam))
    # The lowest eigenvalue reaches zero at divergence: minimise |lambda| over u.
    from scipy.optimize import minimize_scalar
    return minimize_scalar(lowest, bounds=(lo, hi), method="bounded", options={"xatol": 1e-10}).x


if __name__ == "__main__":
    beta = 0.5035
    print("cantilever, beta = %.4f: damped frequency Im(lambda) [and |lambda|] of the lowest three modes" % beta)
    for u in (0.0, 0.27, 0.81, 1.35):
        for coriolis, label in ((1.0, "classical 2 sqrt(b) u"), (0.5, "half Coriolis (seed eq. 3.17 flux)")):
            f = frequencies(u, beta, "clamped-free", coriolis=coriolis)
            print("  u = %.2f %-36s " % (u, label) + "  ".join("%.4f [%.4f]" % (l.imag, abs(l)) for l in f))
    print("rotating cantilever, no flow: frequencies out of the plane of rotation (flap) | in it (lead-lag)")
    for mu in (0.0, 1.0, 2.0, 3.0):
        print("  mu_Omega = %.0f  " % mu + "  ".join("%.4f" % f for f in rotating_frequencies(mu, False)) +
              "  |  " + "  ".join("%.4f" % f for f in rotating_frequencies(mu, True)))
    print("Timoshenko cantilever of pipe_benchmarks::cantilever, Im(lambda):")
    for mu_a, mu_m, u in ((3.9e3, 0.0, 0.0), (1.8e4, 0.5035, 0.0), (1.8e4, 0.5035, 0.27), (1.8e4, 0.5035, 0.81),
                          (1.8e4, 0.5035, 1.35)):
        print("  mu_A = %.3g mu_m = %.4f u = %.2f  " % (mu_a, mu_m, u) +
              "  ".join("%.4f" % f for f in timoshenko_frequencies(u, mu_a, mu_m)))
    print("cantilever flutter, beta = 0.2: u_cf = %.4f" % flutter_threshold(0.2, 4.0, 7.0))
    print("pinned-pinned divergence: u = %.6f (pi = %.6f)" % (divergence_threshold("pinned-pinned", 2.5, 3.8), np.pi))
    print("clamped-clamped divergence: u = %.6f (2 pi = %.6f)" % (divergence_threshold("clamped-clamped", 5.5, 7.0), 2 * np.pi))
