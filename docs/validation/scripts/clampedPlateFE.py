#!/usr/bin/python3
"""Plane-strain finite elements for the clamped plate of hydrostaticPlate2D.

The reference of the tutorial is Euler-Bernoulli (qL^4/384D). A plate with
L/h = 20 also shears, and its clamped end sections cannot warp, so 2D
elasticity itself differs from that formula. This script solves 2D plane
strain with 8-node quadratic elements (3x3 Gauss points): span L = 1 m,
thickness h = 0.05 m, both end sections fully fixed, water pressure
rho_f g H on the top face and the plate's own weight as a body force
(Fourey et al. 2017: E = 67.5 GPa, nu = 0.34, rho_s = 2700, H = 2 m), and
prints the mid-span deflection of the mid-thickness line on meshes refined
twice, against Euler-Bernoulli and Timoshenko (shear factor 5/6).

    /usr/bin/python3 docs/validation/scripts/clampedPlateFE.py

With -cantilever NU it solves instead the static cantilever of docs/vcpm.md
(STATIC_CANTILEVER.md set A: L = 0.2 m, h = 0.02 m, E = 2 MPa, rho = 1000,
own weight at g = 0.0981, plane strain with Poisson ratio NU, the left end
section fully fixed) and prints the tip's centre deflection against
Timoshenko: how much a fully fixed section, which cannot contract sideways,
stiffens 2D elasticity against beam theory.

    /usr/bin/python3 docs/validation/scripts/clampedPlateFE.py -cantilever 0.3
(Debian: python3-numpy, python3-scipy.)
"""
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

cantilever = len(sys.argv) == 3 and sys.argv[1] == "-cantilever"
if cantilever:
    E, nu, rhoS, rhoF, g, H = 2e6, float(sys.argv[2]), 1000.0, 0.0, 0.0981, 0.0
    L, h = 0.2, 0.02
else:
    E, nu, rhoS, rhoF, g, H = 67.5e9, 0.34, 2700.0, 1000.0, 9.81, 2.0
    L, h = 1.0, 0.05


def solve(nx, ny):
    # Nodes of a grid with midside nodes (serendipity: no centre nodes).
    gx, gy = 2*nx + 1, 2*ny + 1
    xs, ys = np.linspace(0, L, gx), np.linspace(-h/2, h/2, gy)
    index = -np.ones((gx, gy), dtype=int)
    coords = []
    for i in range(gx):
        for j in range(gy):
            if i % 2 == 1 and j % 2 == 1:
                continue
            index[i, j] = len(coords)
            coords.append((xs[i], ys[j]))
    coords = np.array(coords)
    n = len(coords)

    # Plane strain elasticity matrix.
    lam = E*nu/((1 + nu)*(1 - 2*nu))
    mu = E/(2*(1 + nu))
    D = np.array([[lam + 2*mu, lam, 0], [lam, lam + 2*mu, 0], [0, 0, mu]])

    # Q8 shape functions on [-1, 1]^2, corners then midsides.
    nodesRef = [(-1, -1), (1, -1), (1, 1), (-1, 1), (0, -1), (1, 0), (0, 1), (-1, 0)]

    def shape(r, s):
        N, dN = np.zeros(8), np.zeros((8, 2))
        for a, (ra, sa) in enumerate(nodesRef[:4]):
            N[a] = 0.25*(1 + ra*r)*(1 + sa*s)*(ra*r + sa*s - 1)
            dN[a, 0] = 0.25*ra*(1 + sa*s)*(2*ra*r + sa*s)
            dN[a, 1] = 0.25*sa*(1 + ra*r)*(ra*r + 2*sa*s)
        for a, (ra, sa) in enumerate(nodesRef[4:], start=4):
            if ra == 0:
                N[a] = 0.5*(1 - r*r)*(1 + sa*s)
                dN[a] = [-r*(1 + sa*s), 0.5*sa*(1 - r*r)]
            else:
                N[a] = 0.5*(1 + ra*r)*(1 - s*s)
                dN[a] = [0.5*ra*(1 - s*s), -s*(1 + ra*r)]
        return N, dN

    gp = [(-np.sqrt(0.6), 5/9), (0.0, 8/9), (np.sqrt(0.6), 5/9)]
    rows, cols, vals = [], [], []
    f = np.zeros(2*n)
    for ex in range(nx):
        for ey in range(ny):
            i0, j0 = 2*ex, 2*ey
            conn = [index[i0, j0], index[i0 + 2, j0], index[i0 + 2, j0 + 2],
                    index[i0, j0 + 2], index[i0 + 1, j0], index[i0 + 2, j0 + 1],
                    index[i0 + 1, j0 + 2], index[i0, j0 + 1]]
            X = coords[conn]
            K = np.zeros((16, 16))
            fe = np.zeros(16)
            for r, wr in gp:
                for s, ws in gp:
                    N, dN = shape(r, s)
                    J = dN.T @ X
                    detJ = np.linalg.det(J)
                    dNx = dN @ np.linalg.inv(J).T
                    B = np.zeros((3, 16))
                    B[0, 0::2] = dNx[:, 0]
                    B[1, 1::2] = dNx[:, 1]
                    B[2, 0::2] = dNx[:, 1]
                    B[2, 1::2] = dNx[:, 0]
                    K += B.T @ D @ B*detJ*wr*ws
                    fe[1::2] += -rhoS*g*N*detJ*wr*ws     # own weight
            if ey == ny - 1:
                # Water pressure on the top edge (s = 1): nodes 3, 2, 6.
                for r, wr in gp:
                    N, dN = shape(r, 1.0)
                    dxdr = dN[:, 0] @ X[:, 0]
                    fe[1::2] += -rhoF*g*H*N*dxdr*wr
            dofs = np.array([[2*c, 2*c + 1] for c in conn]).ravel()
            rows.append(np.repeat(dofs, 16))
            cols.append(np.tile(dofs, 16))
            vals.append(K.ravel())
            f[dofs] += fe
    K = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows),
                       np.concatenate(cols))), shape=(2*n, 2*n))
    fixed = np.zeros(2*n, dtype=bool)
    for j in range(gy):
        for i in ((0,) if cantilever else (0, gx - 1)):
            if index[i, j] >= 0:
                fixed[2*index[i, j]] = fixed[2*index[i, j] + 1] = True
    free = ~fixed
    u = np.zeros(2*n)
    u[free] = spla.spsolve(K[free][:, free].tocsc(), f[free])
    return u[2*index[2*nx if cantilever else nx, ny] + 1]


if cantilever:
    q = -rhoS*g*h
    Ep, G = E/(1 - nu*nu), E/(2*(1 + nu))
    wT = q*L**4/(8*Ep*h**3/12) + q*L*L/(2*(5/6)*G*h)
    print(f"cantilever, plane strain, nu = {nu}: Timoshenko tip {wT:.6e} m")
    for nx, ny in [(40, 4), (80, 8), (160, 16)]:
        w = solve(nx, ny)
        print(f"plane strain Q8 {nx} x {ny}: tip {w:.6e} m, {100*(w/wT - 1):+.3f} % against"
              f" Timoshenko")
    sys.exit(0)


q = g*(rhoF*H + rhoS*h)
Dplate = E*h**3/(12*(1 - nu*nu))
wEB = -q*L**4/(384*Dplate)
G = E/(2*(1 + nu))
wTim = wEB - q*L*L/(8*(5/6)*G*h)
print(f"Euler-Bernoulli {wEB:.5e} m, Timoshenko {wTim:.5e} m ({100*(wTim/wEB - 1):+.2f} %)")
for nx, ny in [(50, 2), (100, 4), (200, 8), (400, 16)]:
    w = solve(nx, ny)
    print(f"plane strain Q8 {nx} x {ny}: {w:.5e} m, {100*(w/wEB - 1):+.2f} % against"
          f" Euler-Bernoulli, {100*(w/wTim - 1):+.2f} % against Timoshenko")
