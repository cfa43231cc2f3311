#include "pfdm/io/nifti_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <set>

#include "nifti2_io.h"
#include "pfdm/util/error.h"

namespace pfdm {

namespace {

namespace fs = std::filesystem;

// Beyond this many voxels a file is not a cardiac label map (ACDC's
// largest 4D image is 2.6e7).
constexpr std::int64_t kMaxVoxels = 400'000'000;
constexpr size_t kMaxLabels = 64;

struct NiftiDeleter {
  void operator()(nifti_image* image) const { nifti_image_free(image); }
};
using NiftiPtr = std::unique_ptr<nifti_image, NiftiDeleter>;

NiftiPtr Open(const std::string& file) {
  if (!fs::is_regular_file(file)) {
    throw InputError(file + ": no such file");
  }
  nifti_set_debug_level(0);  // Its messages would not be one line.
  NiftiPtr image(nifti_image_read(file.c_str(), 1));
  if (!image || image->data == nullptr) {
    throw InputError(file + ": not a readable NIfTI file");
  }
  return image;
}

Eigen::Matrix4d Geometry(const nifti_image& image, std::string* source) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  const nifti_dmat44* from = nullptr;
  if (image.sform_code > 0) {
    from = &image.sto_xyz;
    *source = "sform";
  } else if (image.qform_code > 0) {
    from = &image.qto_xyz;
    *source = "qform";
  }
  if (from == nullptr) {
    *source = "pixdim";
    m.diagonal().head<3>() << image.dx, image.dy, image.dz;
    return m;
  }
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = from->m[r][c];
  }
  return m;
}

double Value(const nifti_image& image, std::int64_t n) {
  const void* d = image.data;
  switch (image.datatype) {
    case DT_UINT8:
      return static_cast<const std::uint8_t*>(d)[n];
    case DT_INT8:
      return static_cast<const std::int8_t*>(d)[n];
    case DT_INT16:
      return static_cast<const std::int16_t*>(d)[n];
    case DT_UINT16:
      return static_cast<const std::uint16_t*>(d)[n];
    case DT_INT32:
      return static_cast<const std::int32_t*>(d)[n];
    case DT_UINT32:
      return static_cast<const std::uint32_t*>(d)[n];
    case DT_INT64:
      return static_cast<double>(static_cast<const std::int64_t*>(d)[n]);
    case DT_UINT64:
      return static_cast<double>(static_cast<const std::uint64_t*>(d)[n]);
    case DT_FLOAT32:
      return static_cast<const float*>(d)[n];
    case DT_FLOAT64:
      return static_cast<const double*>(d)[n];
  }
  return 0.0;
}

void CheckShape(const std::string& file, const nifti_image& image) {
  for (int a = 5; a <= 7 && a <= image.dim[0]; ++a) {
    if (image.dim[a] > 1) {
      throw InputError(file + ": " + std::to_string(image.dim[0]) +
                       "D; a label map is 3D (x, y, slice) or 4D (x, y, "
                       "slice, time)");
    }
  }
  if (image.dim[0] < 3 || image.nz < 2) {
    throw InputError(file +
                     ": a single 2D slice; pfdm needs a stack of "
                     "short-axis slices (x, y, slice[, time])");
  }
  if (image.nx < 2 || image.ny < 2 || image.nvox > kMaxVoxels) {
    throw InputError(file + ": " + std::to_string(image.nx) + " x " +
                     std::to_string(image.ny) + " voxels per slice, " +
                     std::to_string(image.nvox) + " in all: not a label map");
  }
  switch (image.datatype) {
    case DT_UINT8:
    case DT_INT8:
    case DT_INT16:
    case DT_UINT16:
    case DT_INT32:
    case DT_UINT32:
    case DT_INT64:
    case DT_UINT64:
    case DT_FLOAT32:
    case DT_FLOAT64:
      return;
  }
  throw InputError(file + ": voxels of type " +
                   nifti_datatype_string(image.datatype) +
                   ", not labels (whole numbers)");
}

// The voxels as labels, appended: whole numbers (after the file's scaling)
// and few distinct ones.
void AppendLabels(const std::string& file, const nifti_image& image,
                  std::vector<std::int32_t>* labels) {
  const bool scaled = image.scl_slope != 0.0 &&
                      (image.scl_slope != 1.0 || image.scl_inter != 0.0);
  std::set<std::int32_t> seen;
  for (std::int64_t n = 0; n < image.nvox; ++n) {
    double v = Value(image, n);
    if (scaled) v = image.scl_slope * v + image.scl_inter;
    if (!(std::abs(v) < 1e6) || v != std::round(v)) {
      throw InputError(file + ": voxel " + std::to_string(n) + " holds " +
                       std::to_string(v) +
                       ", not a label (a whole number): an image or a "
                       "probability map, not a segmentation");
    }
    const auto label = static_cast<std::int32_t>(v);
    if (seen.size() <= kMaxLabels) seen.insert(label);
    labels->push_back(label);
  }
  if (seen.size() > kMaxLabels) {
    throw InputError(file + ": more than " + std::to_string(kMaxLabels) +
                     " distinct values: an image, not a label map");
  }
}

// The folder's frames in name order (only its *_gt files where it has
// some).
std::vector<std::string> FrameFiles(const std::string& folder) {
  std::vector<std::string> all, gt;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    auto ends = [&](const std::string& tail) {
      return name.size() > tail.size() &&
             name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    if (!ends(".nii") && !ends(".nii.gz")) continue;
    all.push_back(entry.path().string());
    if (name.find("_gt") != std::string::npos) gt.push_back(all.back());
  }
  std::vector<std::string>& files = gt.empty() ? all : gt;
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    throw InputError(folder + ": no .nii or .nii.gz files in this folder");
  }
  return files;
}

}  // namespace

LabelVolume ReadLabelVolume(const std::string& path) {
  const bool folder = fs::is_directory(path);
  const std::vector<std::string> files =
      folder ? FrameFiles(path) : std::vector<std::string>{path};
  LabelVolume volume;
  volume.source = path;
  for (const std::string& file : files) {
    const NiftiPtr image = Open(file);
    CheckShape(file, *image);
    const int nt = image->dim[0] >= 4 ? static_cast<int>(image->nt) : 1;
    std::string geometry;
    const Eigen::Matrix4d m = Geometry(*image, &geometry);
    if (folder && nt > 1) {
      throw InputError(file + ": " + std::to_string(nt) +
                       " frames; a folder holds one 3D file per frame");
    }
    if (volume.nt == 0) {
      volume.nx = static_cast<int>(image->nx);
      volume.ny = static_cast<int>(image->ny);
      volume.nz = static_cast<int>(image->nz);
      volume.world_from_voxel = m;
      volume.geometry = geometry;
    } else if (image->nx != volume.nx || image->ny != volume.ny ||
               image->nz != volume.nz ||
               !m.isApprox(volume.world_from_voxel, 1e-6)) {
      throw InputError(file + ": its grid (size or position) differs from " +
                       files.front() + "'s");
    }
    volume.nt += nt;
    AppendLabels(file, *image, &volume.labels);
  }
  return volume;
}

}  // namespace pfdm
