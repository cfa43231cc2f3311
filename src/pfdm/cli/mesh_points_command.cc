// pfdm mesh-points: corresponding mesh vertices over frames as tracked
// points (id = vertex index), and the contraction measured on the meshes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "pfdm/cli/commands.h"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/io/point_writer.h"
#include "pfdm/report/mesh_motion.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

DEFINE_string(mesh, "",
              "mesh-points: an .obj or legacy .vtk file, a folder "
              "of .obj files (one frame each, in name order) or a CAP "
              "mean_shape.csv");
DEFINE_string(mesh_filter, "",
              "mesh-points: in a folder, only .obj files "
              "whose name contains this");
DEFINE_string(mesh_format, "auto", "mesh-points: obj, vtk, cap-mean or auto");
DEFINE_string(label, "",
              "mesh-points: VTK only, keep the points whose point "
              "scalar equals this (e.g. 0 = endocardium in the UK Digital "
              "Heart mesh); NAME=N picks the array when there are several");
DEFINE_string(cap_surfaces, "ED-endo,ES-endo",
              "mesh-points: CAP surfaces "
              "to take as frames, from ED-endo, ED-epi, ES-endo, ES-epi");

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

std::vector<TriangleMesh> LoadFrames(const std::string& path) {
  std::string format = FLAGS_mesh_format;
  const fs::path p(path);
  if (format == "auto") {
    format = fs::is_directory(p) || p.extension() == ".obj" ? "obj"
             : p.extension() == ".vtk"                      ? "vtk"
             : p.extension() == ".csv"                      ? "cap-mean"
                                                            : "";
    if (format.empty()) {
      throw InputError(path + ": unknown mesh format (use --mesh_format)");
    }
  }
  std::vector<TriangleMesh> frames;
  if (format == "obj") {
    std::vector<std::string> files;
    if (fs::is_directory(p)) {
      for (const auto& entry : fs::directory_iterator(p)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".obj" &&
            name.find(FLAGS_mesh_filter) != std::string::npos) {
          files.push_back(entry.path().string());
        }
      }
      std::sort(files.begin(), files.end());
      if (files.empty()) {
        throw InputError(path + ": no .obj file matching '" +
                         FLAGS_mesh_filter + "'");
      }
    } else {
      files.push_back(path);
    }
    for (const std::string& file : files) frames.push_back(ReadObj(file));
  } else if (format == "vtk") {
    const VtkMesh vtk = ReadLegacyVtkPolyData(path);
    frames.push_back(FLAGS_label.empty() ? vtk.mesh
                                         : KeepLabel(vtk, path, FLAGS_label));
  } else if (format == "cap-mean") {
    const auto surfaces = ReadCapMeanShape(path);
    const auto faces =
        ReadCapFaces((p.parent_path() / "surface_face.csv").string(),
                     static_cast<int>(surfaces.front().size()));
    const std::vector<std::string> names = {"ED-endo", "ED-epi", "ES-endo",
                                            "ES-epi"};
    for (const std::string& wanted : Split(FLAGS_cap_surfaces)) {
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

}  // namespace

int RunMeshPoints() {
  if (FLAGS_mesh.empty()) throw InputError("mesh-points needs --mesh PATH");
  if (FLAGS_out.empty()) throw InputError("mesh-points needs --out FILE.csv");
  const std::vector<TriangleMesh> frames = LoadFrames(FLAGS_mesh);
  std::vector<std::vector<Eigen::Vector3d>> points;
  for (const TriangleMesh& mesh : frames) points.push_back(mesh.points);
  const std::string csv = ToPointsCsv(MeshPointSequence(FLAGS_mesh, points));
  std::vector<MeshFrameMotion> motion;
  if (!frames.front().triangles.empty()) {
    try {
      motion = MeasureMeshMotion(frames);
    } catch (const InputError& error) {  // Say which mesh.
      throw InputError(FLAGS_mesh + ": " + error.what());
    }
  }
  const fs::path out(FLAGS_out);
  if (out.has_parent_path()) EnsureDirectory(out.parent_path().string());
  WriteFileAtomically(FLAGS_out, csv);
  std::printf("wrote %s (%zu frames x %zu vertices)\n", FLAGS_out.c_str(),
              frames.size(), frames.front().points.size());
  if (!motion.empty()) {
    std::printf(
        "measured on the meshes (apex vertex to rim centroid):\n"
        "frame  volume_ml  length_mm  longitudinal_%%  radial_%%\n");
    for (size_t t = 0; t < motion.size(); ++t) {
      std::printf("%5zu  %9.2f  %9.2f  %14.2f  %8.2f\n", t, motion[t].volume_ml,
                  motion[t].length_mm,
                  motion[t].longitudinal_shortening_percent,
                  motion[t].radial_contraction_percent);
    }
  }
  return 0;
}

}  // namespace pfdm
