// Symmetric connectivity for a nearly symmetric mesh: symmetrizes it about its best plane,
// remeshes it so that every vertex, edge and face has a mirror image, decimates that to a fifth of
// its faces keeping the mirrors, and simplifies the input itself to a fifth with a symmetric
// connectivity on its own (asymmetric) surface:
//   symmetric_remeshing [mesh.off] [output_prefix]    (default: CGAL's cow, "cow")
// Writes <prefix>_remeshed.off, <prefix>_fifth.off (symmetric) and <prefix>_simplified.off (on the
// input's surface).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_symmetrization/detect_reflective_symmetries.h>
#include <CGAL/Surface_mesh_symmetrization/symmetric_simplification.h>
#include <CGAL/Surface_mesh_symmetrization/symmetrize.h>

#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMSY = CGAL::Surface_mesh_symmetrization;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : std::string(SHAPE_ANALYSIS_DATA_DIR) + "/cow.off";
  const std::string prefix = argc > 2 ? argv[2] : "cow";
  Mesh input;
  if(!CGAL::IO::read_polygon_mesh(path, input) || faces(input).empty()) {
    std::cerr << "cannot read " << path << "\n";
    return 1;
  }
  try {
    std::vector<SMSY::Symmetry<Kernel>> found;
    SMSY::detect_reflective_symmetries(input, std::back_inserter(found),
                                       SMSY::parameters::maximum_number_of_symmetries(1));
    if(found.empty()) {
      std::cerr << "no reflective symmetry found\n";
      return 1;
    }
    const SMSY::Symmetry<Kernel>& symmetry = found.front();

    // 1. A symmetric surface (the vertices moved, the connectivity kept: mostly, not all, mirrored).
    Mesh mesh = input;
    SMSY::symmetrize(mesh, std::vector<SMSY::Symmetry<Kernel>>{symmetry});

    // 2. A symmetric connectivity, with as many faces as the input.
    const SMSY::Symmetric_remeshing_result r = SMSY::symmetric_remeshing(mesh, symmetry);
    std::cout << "symmetrized: " << 100 * r.before.symmetric_edges << "% of the edges mirrored; remeshed ("
              << r.mirror_points << " mirror points, " << r.flips << " flips, " << r.overlaid_regions
              << " regions of both sides overlaid, " << r.copied_faces << " faces copied across the plane): " << r.faces
              << " faces, " << 100 * r.after.symmetric_edges << "% mirrored\n";
    CGAL::IO::write_polygon_mesh(prefix + "_remeshed.off", mesh, CGAL::parameters::stream_precision(17));

    // 3. Decimated to a fifth, every collapse with its mirror collapse.
    const SMSY::Symmetric_decimation_result d =
      SMSY::symmetric_decimation(mesh, symmetry, SMSY::parameters::number_of_faces(r.faces_before / 5));
    std::cout << "decimated: " << d.faces << " faces, " << 100 * d.after.symmetric_edges << "% mirrored\n";
    CGAL::IO::write_polygon_mesh(prefix + "_fifth.off", mesh, CGAL::parameters::stream_precision(17));

    // 4. The input simplified to a fifth: the same symmetric connectivity, on the input's surface.
    Mesh simplified = input;
    const SMSY::Symmetric_simplification_result s = SMSY::symmetric_simplification(
      simplified, symmetry, SMSY::parameters::number_of_faces(num_faces(input) / 5));
    std::cout << "simplified: " << s.faces << " faces, " << 100 * s.remeshing.after.symmetric_edges
              << "% of the edges mirrored (by their vertex pairs), asymmetries restored\n";
    CGAL::IO::write_polygon_mesh(prefix + "_simplified.off", simplified, CGAL::parameters::stream_precision(17));
    return r.after.symmetric_edges == 1 && d.after.symmetric_edges == 1 ? 0 : 1;
  } catch(const CGAL::Shape_analysis::Bad_input& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
