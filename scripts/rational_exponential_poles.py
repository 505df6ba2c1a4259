#!/usr/bin/python3
# The poles and residues of the local heat kernel's rational approximations of exp(-x)
# on [0, inf) (include/CGAL/Heat_diffusion/internal/rational_exponential.h):
#   exp(-x) ~ sum_k Re(a_k / (-x - z_k)),  Im z_k > 0.
# The poles z_k are those of the Caratheodory-Fejer approximation of type (n, n) of
# exp(z) on (-inf, 0] (Trefethen, Weideman and Schmelzer, "Talbot quadratures and
# rational approximations", BIT 46, 2006, figure 4.1), the residues a_k the fit of
# least maximum error without a constant term (a linear program on a dense grid), so
# that r(inf) = 0. Prints them and the maximum error; needs numpy and scipy.
import numpy as np
from scipy.linalg import hankel, svd
from scipy.optimize import linprog


def caratheodory_fejer_poles(n):
    K, nf, scale = 75, 1024, 9.
    w = np.exp(2j * np.pi * np.arange(nf) / nf)
    t = w.real
    F = np.exp(scale * (t - 1) / (t + 1 + 1e-16))
    c = np.real(np.fft.fft(F)) / nf
    U, S, Vh = svd(hankel(c[1:K + 1]))
    v = Vh.conj().T[:, n]
    roots = np.roots(v)
    q = roots[np.abs(roots) > 1]
    z = scale * (q - 1) ** 2 / (q + 1) ** 2  # poles of exp(z) ~ r(z); exp(-x) = r(-x)
    upper = z[z.imag > 0]
    return upper[np.argsort(upper.imag)]


def grid(x_max, points):
    return np.concatenate([np.linspace(0, x_max, points), np.geomspace(x_max, 1e10, 4000)])


def terms(poles, x):
    columns = []
    for z in poles:
        inverse = 1 / (-x - z)
        columns += [inverse.real, -inverse.imag]  # Re(a / w) = Re a Re(1/w) - Im a Im(1/w)
    return np.array(columns).T


def least_maximum_error_residues(poles):
    x = grid(60., 60001)
    A, y = terms(poles, x), np.exp(-x)
    m, ones = A.shape[1], np.ones((len(x), 1))
    cost = np.zeros(m + 1)
    cost[-1] = 1
    result = linprog(cost, A_ub=np.block([[A, -ones], [-A, -ones]]), b_ub=np.concatenate([y, -y]),
                     bounds=[(None, None)] * m + [(0, None)], method="highs")
    return result.x[0:m:2] + 1j * result.x[1:m:2]


def maximum_error(poles, residues):
    x = grid(100., 400001)
    coefficients = np.ravel(np.column_stack([residues.real, residues.imag]))
    return np.max(np.abs(terms(poles, x) @ coefficients - np.exp(-x)))


for n in (4, 6):
    poles = caratheodory_fejer_poles(n)
    residues = least_maximum_error_residues(poles)
    print("type (%d, %d), %d poles, maximum error %.3g" % (n, n, len(poles), maximum_error(poles, residues)))
    for z, a in zip(poles, residues):
        print("  {%.17g, %.17g, %.17g, %.17g}," % (z.real, z.imag, a.real, a.imag))
