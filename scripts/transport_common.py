"""What the transport-coefficient scripts share: Chapman-Enskog values of elastic hard spheres, the
DSMC's leading-order discretisation laws, the check that a run is of elastic smooth hard spheres,
the conductivity from a heat flux and a T_tr profile, the verdict of --check-theory, the lines of a
--self-check and the scripts' main.

Used by scripts/shear_viscosity.py, scripts/thermal_conductivity.py and scripts/transport_errors.py.

Elastic hard spheres of mass m and diameter sigma (k_B = 1: temperatures are energies):
  eta_0 = (5/(16 sigma^2)) sqrt(m T/pi), kappa_0 = (75/(64 sigma^2)) sqrt(T/(pi m)), the first Sonine
  values; the converged Chapman-Enskog values are eta_CE = 1.016034 eta_0 and kappa_CE = 1.025218
  kappa_0 (Chapman & Cowling 1970); lambda = 1/(sqrt(2) pi n sigma^2), the mean free path.
The DSMC's leading-order laws, transport coefficient over Chapman-Enskog's = 1 + a (dy/lambda)^2 +
b s^2, dy the cell edge along the gradient, s the step in mean free times (dt = s lambda/cbar, cbar =
sqrt(8 T/(pi m)); with c0 = sqrt(2 T/m), the most probable speed, (c0 dt/lambda)^2 = (pi/4) s^2):
  viscosity    a = 16/(45 pi) (Alexander, Garcia & Alder 1998),
               b = 16/(75 pi) (c0 dt/lambda)^2/s^2 = 4/75 (Garcia & Wagner 2000; Hadjiconstantinou 2000);
  conductivity a = 32/(225 pi) (Alexander, Garcia & Alder 1998; 2/5 of the viscosity's),
               b = 32/(225 pi) (c0 dt/lambda)^2/s^2 = 8/225 (Garcia & Wagner 2000; Hadjiconstantinou 2000).
docs/validation.md measures both pairs in Couette and Fourier flow.
"""
import math
import sys

import numpy as np

ETA_CE_OVER_ETA0 = 1.016034  # Chapman & Cowling 1970: the converged rigid-sphere viscosity over its first Sonine value
KAPPA_CE_OVER_KAPPA0 = 1.025218  # the same for the conductivity
VISCOSITY_LAWS = (16.0 / (45.0 * math.pi), 4.0 / 75.0)  # of (dy/lambda)^2 and s^2
CONDUCTIVITY_LAWS = (32.0 / (225.0 * math.pi), 8.0 / 225.0)


class Refused(Exception):
    """The run directory is not one the method applies to."""


def mean_free_path(n, sigma):
    """lambda = 1/(sqrt(2) pi n sigma^2)."""
    return 1.0 / (math.sqrt(2.0) * math.pi * n * sigma ** 2)


def eta_0(m, temperature, sigma):
    """The first Sonine viscosity of hard spheres, (5/(16 sigma^2)) sqrt(m T/pi)."""
    return 5.0 / (16.0 * sigma ** 2) * math.sqrt(m * temperature / math.pi)


def kappa_0(m, temperature, sigma):
    """The first Sonine conductivity of hard spheres, (75/64) sqrt(T/(pi m))/sigma^2."""
    return 75.0 / 64.0 * math.sqrt(temperature / (math.pi * m)) / sigma ** 2


def elastic_smooth_species(case):
    """The one species of a resolved case of elastic smooth hard spheres (constant alpha = 1,
    beta = -1, the hard-sphere kernel, no shear); Refused otherwise."""
    run, species, coll = case.get("run", {}), case.get("species", []), case.get("collision", {})
    if len(species) != 1 or case.get("pair"):
        raise Refused("the method is for one species")
    if (coll.get("model") != "constant" or float(coll.get("alpha", 0)) != 1.0 or float(coll.get("beta", 0)) != -1.0
            or run.get("kernel", "hard_sphere") != "hard_sphere" or run.get("kind", "cooling") != "cooling"):
        raise Refused("the method and its theory are for elastic smooth hard spheres (model \"constant\", alpha = 1, "
                      "beta = -1, kernel \"hard_sphere\", no shear)")
    return species[0]


def kappa_1(y, temperature, q):
    """kappa/sqrt(T) from a uniform heat flux q along y and a T_tr profile T(y): for hard spheres
    kappa = kappa_1 sqrt(T), so -q = kappa_1 sqrt(T) dT/dy = (2/3) kappa_1 d(T^(3/2))/dy and T^(3/2),
    not T, is linear in y; its least-squares slope gives kappa_1 = -(3/2) q/(dT^(3/2)/dy)."""
    slope = np.polyfit(np.asarray(y, float), np.asarray(temperature, float) ** 1.5, 1)[0]
    return -1.5 * q / slope


def check_theory(symbol, ratio, err, tol):
    """The --check-theory verdict: prints it and returns 0 when |ratio - 1| <= tol + 4 err, else 1."""
    bound = tol + 4 * err
    ok = math.isfinite(ratio) and abs(ratio - 1) <= bound
    print(f"check: |{symbol} - 1| = {abs(ratio - 1):.4f} {'<=' if ok else '>'} {tol:g} "
          f"+ 4 x {err:.4f} = {bound:.4f}: {'pass' if ok else 'FAIL'}")
    return 0 if ok else 1


class SelfCheck:
    """The lines of a --self-check: expect(cond, text) prints "ok" or "FAIL" and keeps the failures;
    status() is the exit status."""

    def __init__(self):
        self.failures = []

    def expect(self, cond, text):
        print(f"self-check: {'ok  ' if cond else 'FAIL'} {text}")
        if not cond:
            self.failures.append(text)

    def status(self):
        return 1 if self.failures else 0


def run_cli(name, parser, argv, report, self_check):
    """The scripts' main: --self-check, else report(RUN_DIR, args); exit 2 with the reason when
    the run directory is Refused."""
    args = parser.parse_args(argv[1:])
    if args.self_check:
        return self_check()
    if args.run_dir is None:
        parser.error("RUN_DIR is required (or --self-check)")
    try:
        return report(args.run_dir, args)
    except Refused as e:
        print(f"{name}: {args.run_dir}: {e}", file=sys.stderr)
        return 2
