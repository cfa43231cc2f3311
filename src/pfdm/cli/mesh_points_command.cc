// pfdm mesh-points: corresponding mesh vertices over frames as tracked
// points (id = vertex index), and the contraction measured on the meshes.
#include <cstdio>
#include <filesystem>

#include "pfdm/cli/commands.h"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/io/mesh_source.h"
#include "pfdm/io/point_writer.h"
#include "pfdm/report/mesh_motion.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

namespace {
const pfdm::MeshSettings kDefaults;
}  // namespace

DEFINE_string(mesh, "",
              "mesh-points: an .obj or legacy .vtk file (ASCII or binary), "
              "a folder of .obj or .vtk files (one frame each, in name "
              "order) or a CAP mean_shape.csv");
DEFINE_string(mesh_filter, "",
              "mesh-points: in a folder, only the files "
              "whose name contains this");
DEFINE_string(mesh_format, kDefaults.mesh_format.c_str(),
              "mesh-points: obj, vtk, cap-mean or auto");
DEFINE_string(label, "",
              "mesh-points: VTK only, keep the points whose point "
              "scalar equals this (e.g. 0 = endocardium in the UK Digital "
              "Heart mesh); NAME=N picks the array when there are several");
DEFINE_string(cap_surfaces, kDefaults.cap_surfaces.c_str(),
              "mesh-points: CAP surfaces "
              "to take as frames, from ED-endo, ED-epi, ES-endo, ES-epi");

namespace pfdm {

namespace fs = std::filesystem;

namespace {

MeshSettings MeshSettingsFromFlags() {
  MeshSettings settings;
  settings.mesh_format = FLAGS_mesh_format;
  settings.mesh_filter = FLAGS_mesh_filter;
  settings.label = FLAGS_label;
  settings.cap_surfaces = FLAGS_cap_surfaces;
  return settings;
}

}  // namespace

int RunMeshPoints() {
  if (FLAGS_mesh.empty()) throw InputError("mesh-points needs --mesh PATH");
  if (FLAGS_out.empty()) throw InputError("mesh-points needs --out FILE.csv");
  const std::vector<TriangleMesh> frames =
      ReadMeshFrames(FLAGS_mesh, MeshSettingsFromFlags());
  std::vector<std::vector<Eigen::Vector3d>> points;
  for (const TriangleMesh& mesh : frames) points.push_back(mesh.points);
  PointSequence sequence = MeshPointSequence(FLAGS_mesh, points);
  // The wall the names say, in the CSV's surface column: fit reads it as
  // --surface (an endocardium's volume is the cavity's).
  const WallLayer surface = MeshSurface(FLAGS_mesh, MeshSettingsFromFlags());
  for (Frame& frame : sequence.frames) {
    for (DataPoint& p : frame.points) p.layer = surface;
  }
  const std::string csv = ToPointsCsv(sequence);
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
  if (surface != WallLayer::kAnywhere) {
    std::printf("surface: %s (from the names; fit takes it as --surface)\n",
                surface == WallLayer::kEndocardium ? "endo" : "epi");
  }
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
