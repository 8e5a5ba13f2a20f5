// Particles of a simple polygon (either orientation) laid along its faces, so that sloped
// faces (a wedge's bottom) are smooth lines of particles instead of a Cartesian staircase:
//
// 1. Face layers: for k = 0 .. face_layers−1, the line parallel to each edge at the inward
//    offset d_k = (k+½) dx, trimmed at each end where it meets the neighbouring edge's
//    layer: at a convex vertex of interior angle θ on the angle bisector, i.e. t = d_k /
//    tan(θ/2) in from the vertex; at a reflex vertex on the vertex normal (t = 0). The
//    trimmed length ℓ_k gets n = round(ℓ_k/dx) particles at its centres (spacing ℓ_k/n ≈ dx),
//    each of volume (ℓ_k/n) dx: the strip between offsets k dx and (k+1) dx cut by the
//    bisectors is a trapezoid whose area is exactly ℓ_k dx. At a reflex vertex the annular
//    sector between the two normals (opening φ = θ − π, area φ (k+½) dx²) gets
//    round(φ (k+½)) particles on the arc of radius d_k, or, when that rounds to 0, its area is
//    added to the strip's last particle. A face-layer particle nearer another edge than
//    its own offset (thin parts of the polygon, where layers from opposite faces would cross)
//    is dropped.
// 2. Interior: the cell-centred dx lattice (as before), keeping points inside the polygon
//    whose distance to the boundary is >= face_layers·dx; they share equally the area left
//    over by the face layers (polygon area − face volumes), so the volumes sum to the polygon
//    area (to round-off). Without interior points the residual is spread over all particles.
// 3. Clean-up: a particle closer than dx/2 to an already kept one (sharp corners) is merged
//    into it (its volume added), so no two particles are closer than dx/2.
// layer = k for face particles (0 on the surface), -1 for interior ones.
#pragma once
#include <vector>

#include "geometry/particle_lattice.h"

namespace slamsph {

bool point_in_polygon(Vec2 p, const std::vector<Vec2>& vertices);
double polygon_area(const std::vector<Vec2>& vertices);  // unsigned
// Distance from p to the nearest edge of the closed polygon.
double polygon_boundary_distance(Vec2 p, const std::vector<Vec2>& vertices);
// face_layers >= 1: particle layers laid along every face (3 covers a kernel support of
// 2.6 dx, so the contact never sees the interior lattice's staircase).
ParticleLattice polygon(const std::vector<Vec2>& vertices, double dx, int face_layers = 3);

}  // namespace slamsph
