// Symmetrizes a nearly symmetric mesh about its best plane, writes it, exaggerates and then
// restores its asymmetries, and copies a vertex colour of one side onto the other:
//   symmetrize [mesh.off] [output_prefix]    (default: CGAL's cow, "cow")
// Writes <prefix>_symmetric.off, <prefix>_exaggerated.off (twice the asymmetry) and
// <prefix>_colours.ply (a colour painted on one side, copied onto the other) and
// <prefix>_decimated.off (the symmetrized mesh decimated to half its faces by mirrored collapses).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetric_decimation.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>
#include <CGAL/Surface_mesh_symmetrization/transfer_vertex_attribute.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SMSY = CGAL::Surface_mesh_symmetrization;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/cow.off";
  const std::string prefix = argc > 2 ? argv[2] : "cow";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
    std::cerr << "cannot read " << path << "\n";
    return 1;
  }
  try {
    // 1. The best reflective symmetry (or SMSY::reflective_symmetry<Kernel>(plane) for a known one).
    std::vector<SMSY::Symmetry<Kernel>> found;
    SMSY::detect_reflective_symmetries(mesh, std::back_inserter(found),
                                       SMSY::parameters::maximum_number_of_symmetries(1));
    if(found.empty()) {
      std::cerr << "no symmetry found\n";
      return 1;
    }
    const SMSY::Symmetry<Kernel> symmetry = found.front();
    std::cout << "plane " << symmetry.plane << "\n";

    // 2. Symmetrize: the mesh's vertices move; the result keeps the residuals and the map.
    const SMSY::Symmetrization_result<Kernel> result =
      SMSY::symmetrize(mesh, std::vector<SMSY::Symmetry<Kernel>>{symmetry});
    std::cout << "symmetry error " << result.symmetry_error_before << " -> " << result.symmetry_error_after
              << " of the bounding-box diagonal, distortion " << result.distortion << "\n";
    CGAL::IO::write_polygon_mesh(prefix + "_symmetric.off", mesh, CGAL::parameters::stream_precision(17));

    // 3. Enhancement: amount -1 doubles the asymmetry (1 is symmetric, 0 the input).
    SMSY::enhance_symmetry(mesh, result, -1.0);
    CGAL::IO::write_polygon_mesh(prefix + "_exaggerated.off", mesh, CGAL::parameters::stream_precision(17));
    SMSY::restore_asymmetry(mesh, result); // the input again

    // 4. Attribute transfer: paint a pattern on the positive side only, copy it to the other.
    auto colour = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    for(Mesh::Vertex_index v : vertices(mesh)) {
      const Point& p = mesh.point(v);
      const bool stripe = std::sin(40 * (p.x() + p.y() + p.z())) > 0;
      colour[v] = symmetry.plane.has_on_positive_side(p) ? (stripe ? CGAL::IO::Color(200, 40, 40) : CGAL::IO::Color(240, 220, 200))
                           : CGAL::IO::Color(128, 128, 128);
    }
    // The map of the symmetrized mesh pairs the sides; it is tied to faces, so it works on the
    // restored mesh too.
    SMSY::transfer_vertex_attribute(mesh, symmetry, colour,
                                    SMSY::parameters::symmetric_map(result.symmetric_map[0]));
    CGAL::IO::write_polygon_mesh(prefix + "_colours.ply", mesh, CGAL::parameters::vertex_color_map(colour));

    // 5. The symmetric map of the mesh as it is, without symmetrizing it.
    const std::vector<SMSY::Mirror_point> map = SMSY::compute_symmetric_map(mesh, symmetry);
    double largest = 0;
    for(const SMSY::Mirror_point& m : map)
      largest = (std::max)(largest, m.distance);
    std::cout << "largest distance of a vertex's mirror image to the surface: " << largest << "\n";

    // 6. Symmetric connectivity: the symmetrized surface is symmetric, its mesh mostly so; a
    // decimation that collapses mirror edges together keeps what is.
    Mesh symmetric = mesh;
    SMSY::symmetrize(symmetric, std::vector<SMSY::Symmetry<Kernel>>{symmetry});
    const SMSY::Symmetric_decimation_result d =
      SMSY::symmetric_decimation(symmetric, symmetry, SMSY::parameters::number_of_faces(num_faces(mesh) / 2));
    std::cout << "symmetrized: " << 100 * d.before.paired_vertices << "% of the vertices paired, "
              << 100 * d.before.symmetric_edges << "% of the edges mirrored; decimated to " << d.faces << " faces: "
              << 100 * d.after.symmetric_edges << "% mirrored\n";
    CGAL::IO::write_polygon_mesh(prefix + "_decimated.off", symmetric, CGAL::parameters::stream_precision(17));
    return result.symmetry_error_after < result.symmetry_error_before ? 0 : 1;
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
