#include "pfdm/io/point_file_mistakes.h"

#include <algorithm>
#include <filesystem>

#include "pfdm/util/error.h"

namespace pfdm {
namespace {

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

std::string Extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

bool IsMesh(const std::string& path, const std::string& text) {
  const std::string extension = Extension(path);
  return extension == ".vtk" || extension == ".vtp" || extension == ".obj" ||
         extension == ".ply" || StartsWith(text, "# vtk DataFile") ||
         StartsWith(text, "<?xml") || StartsWith(text, "<VTKFile") ||
         StartsWith(text, "ply\n");
}

}  // namespace

void CheckIsPointCsv(const std::string& path, const std::string& text) {
  if (IsMesh(path, text)) {
    throw InputError(path +
                     ": a mesh, not a points CSV; 'pfdm mesh-points --mesh " +
                     path + " --out points.csv' writes its vertices as points");
  }
  const std::string header = text.substr(0, text.find('\n'));
  if (header.find(',') != std::string::npos) return;
  const char* separator = header.find('\t') != std::string::npos  ? "tabs"
                          : header.find(';') != std::string::npos ? "semicolons"
                                                                  : nullptr;
  if (separator == nullptr) return;
  throw InputError(path + ":1: columns separated by " + separator +
                   "; pfdm reads comma-separated files (frame,id,x,y,z): "
                   "replace the separators with commas");
}

void CheckFramesStartAtZero(const std::string& path, long long first_frame) {
  if (first_frame == 0) return;
  throw InputError(path + ": the first frame is " +
                   std::to_string(first_frame) +
                   "; pfdm numbers frames from 0 (end-diastole by default): "
                   "subtract " +
                   std::to_string(first_frame) + " from the frame column");
}

}  // namespace pfdm
