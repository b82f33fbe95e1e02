// Segments a set of meshes consistently (the same id for the same part in every mesh), prints
// which segments occur in which mesh and which of them are copies of one part within the meshes
// (merge_repeated_segments(): the legs), then labels one more mesh from the segmented set.
//   consistent_segmentation [number_of_segments] mesh1.off mesh2.off ... [--new new_mesh.off]
// Without mesh files: CGAL's cow, bull and elephant, with camel as the new mesh.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Consistent_segmentation/consistent_segmentation.h>
#include <CGAL/Consistent_segmentation/merge_repeated_segments.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;
typedef Mesh::Property_map<face_descriptor, std::size_t> Segment_map;
typedef Mesh::Property_map<face_descriptor, long long> Label_map;
namespace CS = CGAL::Consistent_segmentation;

std::string data_file(const std::string& name)
{
#ifdef SHAPE_ANALYSIS_DATA_DIR // built in this project: CGAL's meshes extracted at configure time
  return std::string(SHAPE_ANALYSIS_DATA_DIR) + "/" + name;
#else
  return CGAL::data_file_path("meshes/" + name);
#endif
}

int main(int argc, char** argv)
{
  std::size_t k = 6;
  std::vector<std::string> files;
  std::string new_file;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--new" && i + 1 < argc)
      new_file = argv[++i];
    else if(i == 1 && arg.find_first_not_of("0123456789") == std::string::npos)
      k = std::strtoul(arg.c_str(), nullptr, 10);
    else
      files.push_back(arg);
  }
  if(files.empty()) {
    files = {data_file("cow.off"), data_file("bull.off"), data_file("elephant.off")};
    new_file = data_file("camel.off");
  }

  std::vector<Mesh> meshes(files.size());
  meshes.reserve(files.size() + 1); // room for the new mesh: property maps stay valid
  for(std::size_t i = 0; i < files.size(); ++i)
    if(!CGAL::IO::read_polygon_mesh(files[i], meshes[i])) {
      std::cerr << "Cannot read " << files[i] << " as a polygon mesh\n";
      return EXIT_FAILURE;
    }

  // One segment id per face of every mesh: a face property map per mesh.
  std::vector<Segment_map> segments;
  for(Mesh& mesh : meshes)
    segments.push_back(mesh.add_property_map<face_descriptor, std::size_t>("f:segment", 0).first);

  try {
    const CS::Consistent_segmentation_result result = CS::consistent_segmentation(
      meshes, segments, CS::parameters::number_of_segments(k).random_seed(1));
    std::cout << result.number_of_segments << " segments over " << meshes.size() << " meshes\n";
    for(std::size_t s = 0; s < result.number_of_segments; ++s) {
      std::cout << "  segment " << s << ": area " << result.segment_area[s] << ", in meshes";
      for(std::size_t m : result.meshes_of_segment[s])
        std::cout << ' ' << m;
      std::cout << '\n';
    }

    // Parts repeated within each mesh (four legs) get one id per place above; one id per kind of
    // part instead, in maps of their own (merge_repeated_segments() rewrites the maps it gets).
    std::vector<Segment_map> kinds;
    for(std::size_t i = 0; i < meshes.size(); ++i) {
      kinds.push_back(meshes[i].add_property_map<face_descriptor, std::size_t>("f:kind", 0).first);
      for(face_descriptor f : faces(meshes[i]))
        kinds[i][f] = segments[i][f];
    }
    CS::Consistent_segmentation_result merged = result;
    const std::size_t removed = CS::merge_repeated_segments(meshes, kinds, merged);
    std::cout << "repeated parts: " << result.number_of_segments << " ids become " << merged.number_of_segments
              << " (" << removed << " merged)\n";
    for(std::size_t s = 0; s < merged.number_of_segments; ++s)
      std::cout << "  kind " << s << ": area " << merged.segment_area[s] << '\n';

    if(new_file.empty())
      return EXIT_SUCCESS;

    // Transfer: the segmented set, as known labels, labels a new mesh. Its faces start unknown
    // (-1); the known faces keep their ids, and the new mesh gets ids of the set.
    Mesh new_mesh;
    if(!CGAL::IO::read_polygon_mesh(new_file, new_mesh)) {
      std::cerr << "Cannot read " << new_file << " as a polygon mesh\n";
      return EXIT_FAILURE;
    }
    meshes.push_back(new_mesh);
    std::vector<Label_map> known;
    std::vector<Segment_map> transferred;
    for(std::size_t i = 0; i < meshes.size(); ++i) {
      known.push_back(meshes[i].add_property_map<face_descriptor, long long>("f:known", -1).first);
      transferred.push_back(meshes[i].add_property_map<face_descriptor, std::size_t>("f:transferred", 0).first);
      if(i + 1 < meshes.size())
        for(face_descriptor f : faces(meshes[i]))
          known[i][f] = static_cast<long long>(segments[i][f]);
    }
    CS::consistent_segmentation(meshes, transferred,
                                CS::parameters::number_of_segments(k).known_segment_maps(known).random_seed(1));
    std::vector<std::size_t> faces_of(result.number_of_segments, 0);
    for(face_descriptor f : faces(meshes.back()))
      ++faces_of[transferred.back()[f]];
    std::cout << "new mesh " << new_file << ": faces per segment id:";
    for(std::size_t n : faces_of)
      std::cout << ' ' << n;
    std::cout << '\n';
  } catch(const CS::Bad_input& e) {
    std::cerr << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
