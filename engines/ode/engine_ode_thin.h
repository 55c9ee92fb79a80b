/* engine_ode_thin: the thin disk as an ODE 0.16 user geom class (DESIGN
 * section 4: one contact, at the lowest point of the rim circle).
 *
 * The disk is a circle of radius r about the geom's local z axis (the body's
 * z1 = n). Against a plane of unit normal N and offset q (N.x = q) it gives
 * exactly one contact: the rim point farthest along -N,
 * L = G - r u / |u| with u = N - (N.n) n, depth q - N.L, normal N pointing
 * into the disk (ODE's convention: into g1, as its sphere-plane collider),
 * or none when L is above the plane. With N = ez, L = G + r d (section 1).
 *
 * The class is registered with dCreateGeomClass on first use, so ODE must be
 * initialised first (dInitODE2); it lives until dCloseODE. Not thread-safe.
 */
#ifndef ENGINE_ODE_THIN_H
#define ENGINE_ODE_THIN_H

#include <ode/ode.h>

/* the thin disk's class number, registering it on the first call */
int dv_ode_thin_class(void);

/* a thin disk of radius r (m) about its local z axis, in no space */
dGeomID dv_ode_thin_create(double radius);

/* the radius of a thin disk geom (m) */
double dv_ode_thin_radius(dGeomID disk);

#endif
