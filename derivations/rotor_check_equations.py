#!/usr/bin/python3
"""Symbolic check of the rotor paper's eqs 2-5, 8-10, 15-20 and 26-30 (Svinin et al.).

Run: /usr/bin/python3 derivations/rotor_check_equations.py   (prints each check; exit 1 on a failure)
"""
import sys
import sympy as sp

t = sp.symbols('t')
k, R = sp.symbols('k R', positive=True)
u = sp.Function('u')(t)
v = sp.Function('v')(t)
p = sp.Function('psi')(t)
ud, vd, pd = sp.diff(u, t), sp.diff(v, t), sp.diff(p, t)
c, s = sp.cos, sp.sin

def Rx(a): return sp.Matrix([[1, 0, 0], [0, c(a), -s(a)], [0, s(a), c(a)]])
def Ry(a): return sp.Matrix([[c(a), 0, s(a)], [0, 1, 0], [-s(a), 0, c(a)]])
def Rz(a): return sp.Matrix([[c(a), -s(a), 0], [s(a), c(a), 0], [0, 0, 1]])

failures = []
def check(name, expr):
    ok = sp.simplify(expr) == 0
    print(('ok   ' if ok else 'FAIL ') + name + ('' if ok else ': residual ' + str(sp.simplify(expr))))
    if not ok:
        failures.append(name)

Rot = Rz(p).T * Rx(v).T * Ry(u).T                      # eq 2
n1p = sp.Matrix([c(u)*c(p) + s(u)*s(v)*s(p), -c(u)*s(p) + s(u)*s(v)*c(p), c(u)*c(v)])  # eq 3 printed
n1r = sp.Matrix([c(u)*c(p) + s(u)*s(v)*s(p), -c(u)*s(p) + s(u)*s(v)*c(p), s(u)*c(v)])  # eq 3 corrected
n2 = sp.Matrix([c(v)*s(p), c(v)*c(p), -s(v)])            # eq 4
n3 = sp.Matrix([-s(u)*c(p) + c(u)*s(v)*s(p), s(u)*s(p) + c(u)*s(v)*c(p), c(u)*c(v)])  # eq 5
print('eq 3 printed n1 - R e1 =', list(sp.simplify(n1p - Rot[:, 0])))
check('eq 3 with n1_z = sin u_o cos v_o', (n1r - Rot[:, 0]).norm()**2)
check('eq 4', (n2 - Rot[:, 1]).norm()**2)
check('eq 5', (n3 - Rot[:, 2]).norm()**2)

cvec = R * sp.Matrix([-s(u)*c(v), s(v), -c(u)*c(v)])   # eq 1
check('eq 1-2: R c(u_o, v_o) is the south pole', (Rot*cvec - sp.Matrix([0, 0, -R])).norm()**2)

W = sp.simplify(sp.diff(Rot, t) * Rot.T)                # omega^ = R' R^T
wx, wy, wz = W[2, 1], W[0, 2], W[1, 0]
check('eq 18', wx - (-ud*c(v)*s(p) - vd*c(p)))
check('eq 19', wy - (-ud*c(v)*c(p) + vd*s(p)))
check('eq 17 (omega_z)', pd - (-wz + s(v)*ud))
check('eq 8', ud - (-(wx*s(p) + wy*c(p))/c(v)))
check('eq 9', vd - (-wx*c(p) + wy*s(p)))
check('eq 10', pd - (-wz - (wx*s(p) + wy*c(p))*sp.tan(v)))
# Rolling without slip: the centre (above the contact point) moves with omega x (0, 0, R).
check('eq 15 (= R omega_y, eq 6)', R*wy - (-R*c(p)*c(v)*ud + R*s(p)*vd))
check('eq 16 (= -R omega_x, eq 7)', -R*wx - (R*s(p)*c(v)*ud + R*c(p)*vd))
# Dynamic realizability, eq 13, solved for omega_z and put into eq 17 gives eq 20.
wz_real = -k*(n3[0]*wx + n3[1]*wy)/n3[2]
check('eq 20', (-wz_real + s(v)*ud) - ((1 - k)*s(v)*ud + k*sp.tan(u)/c(v)*vd))

# Eqs 24-30 in curve form: x, y, z of a point on the sphere of radius R.
x, y, z, xt, yt, zt = sp.symbols('x y z x_t y_t z_t', real=True)
U, V = sp.symbols('U V', real=True)
sub = {x: -R*s(U)*c(V), y: R*s(V), z: -R*c(U)*c(V)}
cu23 = sp.diff(sp.Matrix([-R*s(U)*c(V), R*s(V), -R*c(U)*c(V)]), U)
cv23 = sp.diff(sp.Matrix([-R*s(U)*c(V), R*s(V), -R*c(U)*c(V)]), V)
cu26 = sp.Matrix([z, 0, -x]).subs(sub)
cv26 = sp.Matrix([-x*y/sp.sqrt(R**2 - y**2), sp.sqrt(R**2 - y**2), -y*z/sp.sqrt(R**2 - y**2)]).subs(sub)
assume = {V: sp.Symbol('V')}  # cos V > 0 on the open hemisphere band used
cu26 = cu26.subs(sp.sqrt(R**2 - R**2*s(V)**2), R*c(V))
cv26 = sp.simplify(cv26.subs(sp.sqrt(R**2 - R**2*s(V)**2), R*c(V)))
check('eq 23/26 c_u', (cu23 - cu26).norm()**2)
check('eq 23/26 c_v', (cv23 - cv26).norm()**2)
ct = sp.Matrix([xt, yt, zt])
Ud, Vd = sp.symbols('Ud Vd')
# eq 27 on a tangent c_theta = c_u Ud + c_v Vd.
ctan = cu23*Ud + cv23*Vd
check('eq 27 u_o', (cu23.dot(ctan))/(R**2*c(V)**2) - Ud)
check('eq 27 v_o', (cv23.dot(ctan))/R**2 - Vd)
P = sp.Symbol('P')
w = R*c(V)  # sqrt(R^2 - y^2)
check('eq 28', (-c(P)/w*cu23.dot(ctan) + s(P)/R*cv23.dot(ctan)) - (-R*c(P)*c(V)*Ud + R*s(P)*Vd))
check('eq 29', (s(P)/w*cu23.dot(ctan) + c(P)/R*cv23.dot(ctan)) - (R*s(P)*c(V)*Ud + R*c(P)*Vd))
yv, xv, zv = R*s(V), -R*s(U)*c(V), -R*c(U)*c(V)
psi30 = ((1 - k)*yv*cu23.dot(ctan)/w**2 + k*xv*cv23.dot(ctan)/(zv*w))/R
check('eq 30', psi30 - ((1 - k)*s(V)*Ud + k*sp.tan(U)/c(V)*Vd))

# Eq 35: the circle passes through the south pole, has Euclidean radius a and lies on the sphere.
a, th = sp.symbols('a theta', positive=True)
d = R*sp.sqrt(1 - (a/R)**2)
sa, ca = a/R, d/R
cbar = sp.Matrix([a*s(th), -a*ca*c(th) + d*sa, -a*sa*c(th) - d*ca])
check('eq 35 on the sphere', cbar.dot(cbar) - R**2)
check('eq 35 through the south pole', (cbar.subs(th, 0) - sp.Matrix([0, 0, -R])).norm()**2)
centre = sp.Matrix([0, d*sa, -d*ca])
check('eq 35 Euclidean radius a', (cbar - centre).dot(cbar - centre) - a**2)

sys.exit(1 if failures else 0)
