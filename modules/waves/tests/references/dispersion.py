#!/usr/bin/python3
# High-precision reference for omega^2 = g k tanh(k h): Newton in Python decimal at 60 digits.
from decimal import Decimal as D, getcontext
getcontext().prec = 60
g = D("9.80665")
def tanh(x):
    e = (-2*x).exp()
    return (1-e)/(1+e)
def sech2(x):
    t = tanh(x); return 1 - t*t
def k_of(omega, h):
    w = D(omega); h = D(h)
    y = w*w*h/g
    x = max(y, y.sqrt())
    for _ in range(200):
        f = x*tanh(x) - y
        fp = tanh(x) + x*sech2(x)
        dx = f/fp
        x -= dx
        if abs(dx) < D(10)**-50 * x: break
    return x/h
cases = [("0.05","10"),("0.1","5"),("0.2","20"),("0.3","1"),("0.5","50"),("1.0","30"),
         ("0.6283185307179586","320"),("1.0","320"),("2.0","320"),("2.0","20"),("6.0","320"),("12.566370614359172","320"),("0.01","4000"),("3.0","0.5")]
for w,h in cases:
    k = k_of(w,h)
    print(f"{{{w}, {h}, {k:.20e}}},  // kh = {k*D(h):.6g}, deep ω²/g ratio {(k/(D(w)**2/g)):.6g}")
