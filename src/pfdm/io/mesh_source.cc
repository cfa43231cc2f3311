#include "pfdm/io/mesh_source.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "pfdm/io/legacy_vtk_reader.h"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> Split(const std::string& list) {
  std::vector<std::string> items;
  std::istringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

// Keeps the points whose scalar equals `label` and the triangles among them.
TriangleMesh KeepLabel(const VtkMesh& vtk, const std::string& path,
                       const std::string& label) {
  if (vtk.point_scalars.empty()) {
    throw InputError(path +
                     ": --label given but the file has no point scalars");
  }
  // NAME=N picks the array; a bare N only when there is one to pick.
  const size_t equals = label.find('=');
  const std::string array =
      equals == std::string::npos ? "" : label.substr(0, equals);
  const std::string number =
      equals == std::string::npos ? label : label.substr(equals + 1);
  double wanted = 0.0;
  std::istringstream in(number);
  if (!(in >> wanted) || !(in >> std::ws).eof()) {
    throw InputError("--label must be N or NAME=N, N a number, got '" +
                     Clip(label) + "'");
  }
  auto chosen = vtk.point_scalars.begin();
  if (!array.empty()) {
    chosen = vtk.point_scalars.find(array);
    if (chosen == vtk.point_scalars.end()) {
      throw InputError(path + ": no point scalars named '" + Clip(array) + "'");
    }
  } else if (vtk.point_scalars.size() > 1) {
    std::string names;
    for (const auto& [name, values] : vtk.point_scalars) {
      names += (names.empty() ? "" : ", ") + name;
    }
    throw InputError(path + ": --label " + Clip(label) +
                     " is ambiguous, the file has point scalars " +
                     Clip(names, 80) + "; give --label NAME=" + number);
  }
  const std::vector<double>& values = chosen->second;
  std::vector<int> new_index(vtk.mesh.points.size(), -1);
  TriangleMesh kept;
  for (size_t i = 0; i < values.size() && i < vtk.mesh.points.size(); ++i) {
    if (values[i] != wanted) continue;
    new_index[i] = static_cast<int>(kept.points.size());
    kept.points.push_back(vtk.mesh.points[i]);
  }
  if (kept.points.empty()) {
    throw InputError(path + ": no point has label " + label);
  }
  for (const auto& t : vtk.mesh.triangles) {
    if (new_index[t[0]] < 0 || new_index[t[1]] < 0 || new_index[t[2]] < 0)
      continue;
    kept.triangles.push_back(
        {new_index[t[0]], new_index[t[1]], new_index[t[2]]});
  }
  return kept;
}

// pfdm fit's own frames hold the data points after the model's vertices
// (point scalar is_data = 1), in each frame's order: taken as vertices of
// one mesh, they would pair points of different frames by position in the
// file.  Refused, with the flag that keeps the vertices.
void CheckNotPfdmData(const VtkMesh& vtk, const std::string& path) {
  const auto it = vtk.point_scalars.find("is_data");
  if (it == vtk.point_scalars.end()) return;
  for (double value : it->second) {
    if (value != 0.0) {
      throw InputError(path +
                       ": a pfdm frame with its data points (is_data = 1); "
                       "--label is_data=0 keeps the model's vertices");
    }
  }
}

// The files of `path` with `extension` whose names contain `filter`, in
// name order: one frame each; or `path` itself when it is a file.
std::vector<std::string> FrameFiles(const fs::path& path,
                                    const std::string& extension,
                                    const std::string& filter) {
  if (!fs::is_directory(path)) return {path.string()};
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(path)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == extension &&
        name.find(filter) != std::string::npos) {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    throw InputError(path.string() + ": no " + extension + " file matching '" +
                     filter + "'");
  }
  return files;
}

// A folder's format: its meshes' extension, .obj where it has both.
std::string FolderFormat(const fs::path& path) {
  bool vtk = false;
  for (const auto& entry : fs::directory_iterator(path)) {
    if (entry.path().extension() == ".obj") return "obj";
    vtk = vtk || entry.path().extension() == ".vtk";
  }
  return vtk ? "vtk" : "obj";
}

std::string MeshFormat(const std::string& path, const MeshSettings& settings) {
  std::string format = settings.mesh_format;
  const fs::path p(path);
  if (format == "auto") {
    format = fs::is_directory(p)       ? FolderFormat(p)
             : p.extension() == ".obj" ? "obj"
             : p.extension() == ".vtk" ? "vtk"
             : p.extension() == ".csv" ? "cap-mean"
                                       : "";
    if (format.empty()) {
      throw InputError(path + ": unknown mesh format (use --mesh_format)");
    }
  }
  return format;
}

// The wall every name says, by its ending ("-endo") or a part of it
// ("LV_ENDOCARDIAL"), else kAnywhere.
WallLayer WallNamed(const std::vector<std::string>& names) {
  bool endo = !names.empty(), epi = !names.empty();
  for (std::string name : names) {
    std::transform(name.begin(), name.end(), name.begin(), ::toupper);
    const bool is_endo = name.find("ENDO") != std::string::npos;
    endo = endo && is_endo;
    epi = epi && !is_endo && name.find("EPI") != std::string::npos;
  }
  return endo  ? WallLayer::kEndocardium
         : epi ? WallLayer::kEpicardium
               : WallLayer::kAnywhere;
}

}  // namespace

WallLayer MeshSurface(const std::string& path, const MeshSettings& settings) {
  const std::string format = MeshFormat(path, settings);
  if (format == "cap-mean") return WallNamed(Split(settings.cap_surfaces));
  // A label's number means what the mesh's maker chose.
  if (!settings.label.empty() || (format != "obj" && format != "vtk")) {
    return WallLayer::kAnywhere;
  }
  std::vector<std::string> names;
  for (const std::string& file :
       FrameFiles(fs::path(path), "." + format, settings.mesh_filter)) {
    names.push_back(fs::path(file).filename().string());
  }
  return WallNamed(names);
}

std::vector<TriangleMesh> ReadMeshFrames(const std::string& path,
                                         const MeshSettings& settings) {
  const std::string format = MeshFormat(path, settings);
  const fs::path p(path);
  std::vector<TriangleMesh> frames;
  if (format == "obj") {
    for (const std::string& file : FrameFiles(p, ".obj", settings.mesh_filter))
      frames.push_back(ReadObj(file));
  } else if (format == "vtk") {
    for (const std::string& file :
         FrameFiles(p, ".vtk", settings.mesh_filter)) {
      const VtkMesh vtk = ReadLegacyVtkPolyData(file);
      if (settings.label.empty()) CheckNotPfdmData(vtk, file);
      frames.push_back(settings.label.empty()
                           ? vtk.mesh
                           : KeepLabel(vtk, file, settings.label));
    }
  } else if (format == "cap-mean") {
    const auto surfaces = ReadCapMeanShape(path);
    const auto faces =
        ReadCapFaces((p.parent_path() / "surface_face.csv").string(),
                     static_cast<int>(surfaces.front().size()));
    const std::vector<std::string> names = {"ED-endo", "ED-epi", "ES-endo",
                                            "ES-epi"};
    for (const std::string& wanted : Split(settings.cap_surfaces)) {
      const auto it = std::find(names.begin(), names.end(), wanted);
      if (it == names.end()) {
        throw InputError("--cap_surfaces: unknown surface '" + wanted +
                         "' (expected ED-endo, ED-epi, ES-endo or ES-epi)");
      }
      frames.push_back({surfaces[it - names.begin()], faces});
    }
  } else {
    throw InputError("unknown --mesh_format '" + format +
                     "' (expected obj, vtk, cap-mean or auto)");
  }
  if (frames.empty()) throw InputError(path + ": no frames");
  return frames;
}

PointSequence ReadMeshPoints(const std::string& path,
                             const MeshSettings& settings) {
  std::vector<std::vector<Eigen::Vector3d>> points;
  for (const TriangleMesh& mesh : ReadMeshFrames(path, settings)) {
    points.push_back(mesh.points);
  }
  PointSequence sequence = MeshPointSequence(path, points);
  const WallLayer surface = MeshSurface(path, settings);
  for (Frame& frame : sequence.frames) {
    for (DataPoint& p : frame.points) p.layer = surface;
  }
  return sequence;
}

}  // namespace pfdm
