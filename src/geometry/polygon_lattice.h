// Particles of a simple polygon (either orientation), filled in one of two ways
// (`[body.shape] fill`, docs/case_format.md; docs/model.md §4 "Polygon bodies"):
//
// PolygonFill::Cartesian — the cell-centred dx lattice over the bounding box, keeping the
// cell centres inside the polygon (even–odd rule), each of volume dx². A sloped face is a
// staircase; the total converges to the area as dx → 0 and is exact for axis-aligned
// rectangles whose sides are multiples of dx.
//
// PolygonFill::Faces — particles laid along the faces, so that sloped faces (a wedge's
// bottom) are straight lines of particles:
// 1. Face layers: for k = 0 .. face_layers−1, the line parallel to each edge at the inward
//    offset d_k = (k+½) dx, trimmed at each end where it meets the neighbouring edge's
//    layer: at a convex vertex of interior angle θ on the angle bisector (t = d_k/tan(θ/2)
//    in from the vertex), at a reflex vertex on the vertex normal (t = 0). The trimmed
//    length ℓ_k gets n = round(ℓ_k/dx) particles at its centres (spacing ℓ_k/n ≈ dx), each
//    of volume (ℓ_k/n) dx: the strip between offsets k dx and (k+1) dx cut by the
//    bisectors is a trapezoid of area exactly ℓ_k dx. At a reflex vertex the annular sector
//    between the two normals (opening φ = θ − π, area φ (k+½) dx²) gets round(φ (k+½))
//    particles on the arc of radius d_k, or, when that rounds to 0, its area goes to the
//    strip's last particle. A face particle nearer another edge than its own offset (thin
//    parts, where layers from opposite faces would cross) is dropped.
// 2. Interior: the cell-centred dx lattice, keeping points inside the polygon whose distance
//    to the boundary is >= face_layers·dx; they share equally the area the face layers
//    leave (polygon area − face volumes), so the volumes sum to the polygon area (to
//    round-off). Without interior points the residual is spread over all particles.
// 3. Clean-up: a particle closer than kFaceFillMinGap·dx to an already kept one (sharp
//    corners, the face/interior junction) is merged into it (its volume added), so no two
//    particles are closer than kFaceFillMinGap·dx and the volumes still sum to the area.
// layer = k for face particles (0 on the surface), -1 for interior (and Cartesian) ones.
// The junction between the face layers and the interior lattice is irregular (pairs down
// to kFaceFillMinGap·dx, gaps up to ~1.5 dx): fine for rigid bodies (the contact sees the
// face layers and the colour-gradient normals), not for TL-SFPM (docs/model.md §3), so
// the case parser refuses fill = "faces" on elastic bodies.
#pragma once
#include <vector>

#include "geometry/particle_lattice.h"

namespace slamsph {

enum class PolygonFill { Cartesian, Faces };

// Smallest pair distance the face fill keeps, in units of dx (clean-up, step 3).
inline constexpr double kFaceFillMinGap = 0.5;
// Face layers of the face fill: 3 cover the Wendland C2 support 2h = 2.76 dx at h/dx =
// 1.38, so a surface particle's kernel never reaches the interior lattice.
inline constexpr int kFaceFillLayers = 3;

bool point_in_polygon(Vec2 p, const std::vector<Vec2>& vertices);
double polygon_area(const std::vector<Vec2>& vertices);  // unsigned
// Distance from p to the nearest edge of the closed polygon.
double polygon_boundary_distance(Vec2 p, const std::vector<Vec2>& vertices);
ParticleLattice polygon(const std::vector<Vec2>& vertices, double dx,
                        PolygonFill fill = PolygonFill::Cartesian,
                        int face_layers = kFaceFillLayers);

}  // namespace slamsph
