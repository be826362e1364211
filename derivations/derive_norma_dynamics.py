#!/usr/bin/python3
"""Symbolic derivation of Norma's dynamics (Moazami, Palanki, Zargarzadeh 2019).

Builds the Lagrangian of eq 45 (text, eqs 7-44) with q = [theta, alpha, phi, delta], derives
M(q) (A.1), the Christoffel C(q, qd) (A.23, A.24) and G(q) (A.41), checks them against the
appendix entries A.3-A.21, A.28-A.45 (transcribed below) and prints every disagreement with the
term that causes it. With --emit-cpp FILE it writes the C++ evaluation of M, dM/d(beta, phi,
delta) and G of the text's Lagrangian, which src/norma/norma_dynamics.cpp includes; the appendix
variant differs from it by one term of M11 only, which this script identifies and checks.

Run:  /usr/bin/python3 derivations/derive_norma_dynamics.py [--emit-cpp src/norma/norma_dynamics_generated.inc]
"""
import argparse
import random
import sys

import sympy as sp
from sympy.printing.cxx import CXX17CodePrinter
from sympy.printing.precedence import PRECEDENCE

th, al, ph, de = sp.symbols('theta alpha phi delta', real=True)
thd, ald, phd, ded = sp.symbols('thetad alphad phid deltad', real=True)
q = [th, al, ph, de]
qd = [thd, ald, phd, ded]
R, L, L0, d0, g = sp.symbols('R L L0 delta0 g', positive=True)
m_shl, m_shf, m_p, m_sl = sp.symbols('m_shl m_shf m_p m_sl', positive=True)

m_sp = m_shl + m_shf                     # text after eq 21: Sp is shell plus shaft
I_shl = sp.Rational(2, 3) * m_shl * R**2  # eq 38 (thin spherical shell)
I_shf = sp.Rational(1, 3) * m_shf * R**2  # eq 39 with m_Shf (the paper prints m_Shl): rod of length 2R

C, S = sp.cos, sp.sin
b = al - th          # pendulum angle relative to its rest direction (text above eq 15)
d = de + d0          # slider distance from O_Sp (eq 18)
Cb, Sb, Cp, Sp_ = C(b), S(b), C(ph), S(ph)


def text_lagrangian_parts():
    """Eq 45 term by term, as printed (I_Shf in its fourth term read as I_Shf^x, eq 40)."""
    T_sp = (sp.Rational(1, 2) * m_sp * ((R * thd * Cp)**2 + (-R * phd)**2)
            + sp.Rational(1, 2) * (I_shl + I_shf) * phd**2
            + sp.Rational(1, 2) * (I_shl + I_shf * Sp_**2) * (thd * Cp)**2
            + sp.Rational(1, 2) * (I_shl + I_shf * Cp**2) * (-thd * Sp_)**2)
    bd = ald - thd
    T_p = (sp.Rational(1, 2) * m_p * ((R * thd * Cp + L * bd * Cb)**2
                                      + ((L0 * Sp_ + L * Cb * Cp - R) * phd - L * bd * Sb * Sp_)**2
                                      + (L * bd * Sb * Cp + (-L0 * Cp + L * Cb * Sp_) * phd)**2)
           + sp.Rational(1, 2) * m_p * (L0**2 + (L * Cb)**2) * phd**2
           + sp.Rational(1, 2) * m_p * (L * Cb * Cp + L0 * Sp_)**2 * ((thd - ald) * Cp)**2
           + sp.Rational(1, 2) * m_p * (L0 * Cp - L * Sp_)**2 * ((ald - thd) * Sp_)**2)
    T_sl = (sp.Rational(1, 2) * m_sl * ((R * thd * Cp)**2 + (ded * Cp - (R + d * Sp_) * phd)**2
                                        + (ded * Sp_ + d * Cp * phd)**2)
            + sp.Rational(1, 2) * m_sl * d**2 * phd**2
            + sp.Rational(1, 2) * m_sl * (d * Sp_)**2 * (thd * Cp)**2
            + sp.Rational(1, 2) * m_sl * (d * Cp)**2 * (-thd * Sp_)**2)
    V = m_sl * g * d * Sp_ - m_p * g * (L * Cb * Cp + L0 * Sp_)  # eq 20
    return T_sp + T_p + T_sl, V


def appendix_M():
    """A.3-A.21 as printed (A.15's garbled bracket closed after S_phi)."""
    M = sp.zeros(4, 4)
    M[0, 0] = (L**2 * m_p * Cb**2 * (1 + Cp**4) - 2 * L * L0 * m_p * Cp * Sp_**3
               + 2 * L * m_p * Cb * Cp * (L0 * Cp**2 * Sp_ - R) + L**2 * m_p * Sp_**2 * (Sb**2 + Sp_**2)
               + Cp**2 * (I_shl + (m_p + m_sl + m_sp) * R**2 + L**2 * m_p * Sb**2
                          + (I_shf + 2 * (L0**2 * m_p + m_sl * d**2)) * Sp_**2))
    M[0, 1] = -m_p * (L**2 * Cb**2 * (1 + Cp**4) - 2 * L * L0 * Cp * Sp_**3
                      + L * Cb * Cp * (2 * L0 * Cp**2 * Sp_ - R) + L**2 * Sp_**2 * (Sb**2 + Sp_**2)
                      + Cp**2 * (L**2 * Sb**2 + 2 * L0**2 * Sp_**2))
    M[0, 2] = L * m_p * Sb * (L0 - R * Sp_)
    M[1, 1] = m_p * (L**2 * Cb**2 + L**2 * Cp**2 * Sb**2 + Sp_**2 * ((L0 * Cp - L * Sp_)**2 + L**2 * Sb**2)
                     + Cp**2 * (L * Cb * Cp + L0 * Sp_)**2)
    M[1, 2] = -L * m_p * Sb * (L0 - R * Sp_)
    M[2, 2] = (I_shl + I_shf + 2 * m_sl * d**2 + (m_p + m_sl + m_sp) * R**2
               + m_p * (L**2 * (1 + C(2 * b)) + 2 * L0**2 - 2 * R * L * Cb * Cp)
               + 2 * R * (m_sl * d - L0 * m_p) * Sp_)
    M[2, 3] = -m_sl * R * Cp
    M[3, 3] = m_sl
    for i in range(4):
        for j in range(i):
            M[i, j] = M[j, i]  # A.8, A.13, A.14, A.18-A.20
    return M


def appendix_G():
    """A.42-A.45."""
    return sp.Matrix([-g * L * m_p * Cp * Sb, g * L * m_p * Cp * Sb,
                      g * ((m_sl * d - L0 * m_p) * Cp + L * m_p * Cb * Sp_), g * m_sl * Sp_])


def appendix_C_legible():
    """The C entries whose OCR is legible: A.28 (C14), A.32 (C24), A.36 (C34), A.37-A.40."""
    return {(0, 3): 2 * m_sl * thd * d * Cp**2 * Sp_**2, (1, 3): sp.Integer(0),
            (2, 3): m_sl * phd * (2 * d + R * Sp_), (3, 0): -2 * m_sl * d * Cp**2 * thd * Sp_**2,
            (3, 1): sp.Integer(0), (3, 2): -2 * m_sl * d * phd, (3, 3): sp.Integer(0)}


def inertia_matrix(T):
    return sp.Matrix(4, 4, lambda i, j: sp.diff(T, qd[i], qd[j]))


def christoffel(M):
    """A.23, A.24: C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k."""
    Cm = sp.zeros(4, 4)
    for i in range(4):
        for j in range(4):
            Cm[i, j] = sum(sp.Rational(1, 2) * (sp.diff(M[i, j], q[k]) + sp.diff(M[i, k], q[j])
                                                - sp.diff(M[j, k], q[i])) * qd[k] for k in range(4))
    return Cm


PARAMS = {R: 0.2, L: 0.15, L0: 0.10, d0: 0.1, g: 9.81, m_shl: 2.5, m_shf: 0.5, m_p: 0.5, m_sl: 0.5}


def numeric_gap(a, b, trials=20):
    """Largest |a - b| over random states at the section-5 parameters."""
    f = sp.lambdify(q + qd, (a - b).subs(PARAMS), 'math')
    rng = random.Random(5)
    worst = 0.0
    for _ in range(trials):
        x = [rng.uniform(-3, 3) for _ in range(3)] + [rng.uniform(-0.1, 0.1)] + \
            [rng.uniform(-2, 2) for _ in range(4)]
        worst = max(worst, abs(float(f(*x))))
    return worst


def compare(T, V):
    M = inertia_matrix(T)
    G = sp.Matrix([sp.diff(V, qi) for qi in q])
    Ma, Ga = appendix_M(), appendix_G()
    names = ['theta', 'alpha', 'phi', 'delta']
    print('# M (A.3-A.21): text Lagrangian (eq 45) vs appendix')
    disagreements = []
    for i in range(4):
        for j in range(i, 4):
            gap = numeric_gap(M[i, j], Ma[i, j])
            status = 'agree' if gap < 1e-12 else 'DIFFER (max |gap| %.3e)' % gap
            print('M%d%d: %s' % (i + 1, j + 1, status))
            if gap >= 1e-12:
                diff = sp.simplify(sp.trigsimp(sp.expand(M[i, j] - Ma[i, j])))
                print('   text - appendix =', diff)
                disagreements.append((i, j, diff))
    # The one disagreement, identified: the appendix's M11 lacks the shell-and-shaft yaw term
    # 1/2 I_Sp^z (-thetad S_phi)^2 of eq 37 (I_Sp^z = I_Shl + I_Shf^x C_phi^2, eq 40).
    yaw_term = (I_shl + I_shf * Cp**2) * Sp_**2
    assert sp.simplify(M[0, 0] - Ma[0, 0] - yaw_term) == 0
    assert all(sp.simplify(M[i, j] - Ma[i, j]) == 0 for i in range(4) for j in range(4) if (i, j) != (0, 0))
    print('=> appendix M = text M - (I_Shl + I_Shf^x C_phi^2) S_phi^2 e1 e1^T exactly '
          '(the sphere\'s yaw kinetic energy, last term of eq 37, is missing from A.3)')
    print('# G (A.42-A.45)')
    for i in range(4):
        gap = numeric_gap(G[i], Ga[i])
        print('G%d: %s' % (i + 1, 'agree' if gap < 1e-12 else 'DIFFER %.3e: %s' % (
            gap, sp.simplify(G[i] - Ga[i]))))
    print('# C (A.23-A.40), legible entries, Christoffel of text M and of appendix M')
    Ct, Ca = christoffel(M), christoffel(Ma)
    for (i, j), printed in appendix_C_legible().items():
        gt, ga = numeric_gap(Ct[i, j], printed), numeric_gap(Ca[i, j], printed)
        print('C%d%d: printed vs text-derived %s, vs appendix-M-derived %s' % (
            i + 1, j + 1, 'agree' if gt < 1e-12 else 'DIFFER %.3e' % gt,
            'agree' if ga < 1e-12 else 'DIFFER %.3e' % ga))
        if gt >= 1e-12:
            print('   derived from text M:', sp.factor(sp.simplify(Ct[i, j])))
    return M, G, Ma, Ga, disagreements


class ProductPowerPrinter(CXX17CodePrinter):
    """Writes small integer powers as products: std::pow is not reduced to them without
    -ffast-math, and the evaluation must stay well under a microsecond."""

    def _print_Pow(self, expr):
        base, exp = expr.as_base_exp()
        if exp.is_Integer and 2 <= exp <= 4:
            b = self.parenthesize(base, PRECEDENCE['Mul'])
            return '*'.join([b] * int(exp))
        return super()._print_Pow(expr)


def emit_cpp(path, M, G):
    """C++ for M, dM/dbeta, dM/dphi, dM/ddelta and G; M depends on theta and alpha only via beta."""
    bb = sp.Symbol('beta', real=True)
    sb, cb, sf, cf, dd = sp.symbols('sb cb sf cf d', real=True)
    Mb, Gb = M.subs(al, bb + th), G.subs(al, bb + th)
    exprs, labels = [], []
    upper = [(i, j) for i in range(4) for j in range(i, 4)]
    for i, j in upper:
        exprs.append(Mb[i, j]); labels.append('m(%d, %d)' % (i, j))
    for k, var in enumerate([bb, ph, de]):
        for i, j in upper:
            exprs.append(sp.diff(Mb[i, j], var)); labels.append('dm[%d](%d, %d)' % (k, i, j))
    for i in range(4):
        exprs.append(Gb[i]); labels.append('gv(%d)' % i)
    rep = {sp.sin(bb): sb, sp.cos(bb): cb, sp.sin(ph): sf, sp.cos(ph): cf}
    exprs = [sp.expand(sp.expand(sp.expand_trig(e)).subs(rep).subs(de, dd - d0)) for e in exprs]
    for e in exprs:
        if e.free_symbols & {th, al, bb, ph, de}:
            raise RuntimeError('trig substitution incomplete: %s' % e.free_symbols)
    pmap = {R: 'p.R', L: 'p.L', L0: 'p.L0', d0: 'p.delta0', g: 'p.g', m_shl: 'p.m_shell',
            m_shf: 'p.m_shaft', m_p: 'p.m_pendulum', m_sl: 'p.m_slider'}
    psub = {k: sp.Symbol(v) for k, v in pmap.items()}
    subs_, reduced = sp.cse([e.subs(psub) for e in exprs], symbols=sp.numbered_symbols('x'))
    lines = ['// Generated by derivations/derive_norma_dynamics.py --emit-cpp FILE: do not edit by hand.',
             '// The text Lagrangian (eq 45): M(q) (A.1), its partial derivatives with respect to',
             '// beta = alpha - theta, phi and delta, and G(q) (A.41). Inputs: sb, cb = sin, cos beta;',
             '// sf, cf = sin, cos phi; d = delta0 + delta; p the parameters. Writes the upper',
             '// triangles of m and dm[0..2], and gv.',
             'inline void evaluateTextTerms(const NormaParameters& p, double sb, double cb, double sf,',
             '                              double cf, double d, Eigen::Matrix4d& m,',
             '                              std::array<Eigen::Matrix4d, 3>& dm, Eigen::Vector4d& gv) {']
    printer = ProductPowerPrinter()
    for s_, e in subs_:
        lines.append('  const double %s = %s;' % (s_, printer.doprint(e)))
    for lab, e in zip(labels, reduced):
        lines.append('  %s = %s;' % (lab, printer.doprint(e)))
    lines.append('}')
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--emit-cpp', metavar='FILE')
    args = ap.parse_args()
    T, V = text_lagrangian_parts()
    M, G, Ma, Ga, _ = compare(T, V)
    if args.emit_cpp:
        emit_cpp(args.emit_cpp, M, G)
        print('wrote', args.emit_cpp)
    return 0


if __name__ == '__main__':
    sys.exit(main())
