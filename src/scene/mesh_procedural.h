// Procedural local-space shapes (internal to ps_scene); build_surface_mesh() transforms them.
#pragma once

#include "core/result.h"
#include "scene/mesh.h"

namespace ps::mesh_detail {

// size_mm.x by size_mm.y in local XY centred at the origin, normal +Z; resolution^2 quads.
Mesh make_plane(glm::dvec2 size_mm, int resolution);
// UV sphere: `resolution` segments around Z, resolution/2 (at least 2) rings pole to pole.
Mesh make_sphere(double radius_mm, int resolution);
// Ring torus around local Z: `resolution` segments around Z, resolution/2 (>= 3) around the tube.
Mesh make_torus(double major_radius_mm, double minor_radius_mm, int resolution);
// Axis-aligned box centred at the origin, full edge lengths size_mm: six faces of two
// triangles each, with their own four vertices so every face has its flat normal.
Mesh make_box(glm::dvec3 size_mm);
// Height field over size_mm from a grey image: z = height_mm * value (bilinear).
Result<Mesh> make_height_field(const std::string& image_path, glm::dvec2 size_mm,
                               double height_mm, int resolution);

// type = "fourd": the 3D image of the surface embedded in R^4 (fourd/fourd_mesh.h) times
// `scale`, each vertex coloured by its 4D depth (fourd::depth_colour).
Result<Mesh> make_fourd_mesh(const Surface& surface);

void compute_bounds(Mesh& mesh);

}  // namespace ps::mesh_detail
