#include "pfdm/segmentation/mask_contours.h"

#include <cmath>
#include <cstdio>
#include <functional>

#include "pfdm/segmentation/boundary_points.h"
#include "pfdm/segmentation/rv_contact.h"
#include "pfdm/segmentation/slice_alignment.h"
#include "pfdm/util/error.h"

namespace pfdm {

namespace {

SliceMask MaskOf(const LabelVolume& volume, int k, int t,
                 const std::function<bool(std::int32_t)>& in) {
  SliceMask mask;
  mask.nx = volume.nx;
  mask.ny = volume.ny;
  mask.inside.resize(static_cast<size_t>(volume.nx) * volume.ny);
  for (int j = 0; j < volume.ny; ++j) {
    for (int i = 0; i < volume.nx; ++i) {
      mask.inside[j * volume.nx + i] = in(volume.At(i, j, k, t)) ? 1 : 0;
    }
  }
  return mask;
}

struct Masks {
  SliceMask cavity, myocardium, lv;  // lv: cavity and myocardium.
};

Masks MasksOf(const LabelVolume& volume, const LabelMap& labels, int k, int t) {
  return {MaskOf(volume, k, t, [&](std::int32_t v) { return v == labels.lv; }),
          MaskOf(volume, k, t, [&](std::int32_t v) { return v == labels.myo; }),
          MaskOf(volume, k, t, [&](std::int32_t v) {
            return v == labels.lv || v == labels.myo;
          })};
}

void CheckHasLv(const LabelVolume& volume, const LabelMap& labels) {
  for (std::int32_t v : volume.labels) {
    if (v == labels.lv) return;
  }
  throw InputError(volume.source +
                   ": no voxel labelled lv=" + std::to_string(labels.lv) +
                   " (the LV cavity); --labels says which value is which "
                   "(e.g. --labels acdc, mnms or lv=3,myo=2,rv=1)");
}

// Whether a myocardium voxel is one of the four around the fractional
// point p: a cavity boundary point between the cavity and the myocardium.
bool BordersMyocardium(const SliceMask& myocardium, const Eigen::Vector2d& p) {
  const int i = static_cast<int>(std::floor(p.x()));
  const int j = static_cast<int>(std::floor(p.y()));
  return myocardium.At(i, j) || myocardium.At(i + 1, j) ||
         myocardium.At(i, j + 1) || myocardium.At(i + 1, j + 1);
}

double MyocardialCover(const Masks& masks) {
  const std::vector<Eigen::Vector2d> boundary = BoundaryPoints(masks.cavity);
  if (boundary.empty()) return 0.0;
  int covered = 0;
  for (const Eigen::Vector2d& p : boundary) {
    covered += BordersMyocardium(masks.myocardium, p);
  }
  return static_cast<double>(covered) / boundary.size();
}

SliceRing MeasureRing(const LabelVolume& volume, const Masks& masks, int k,
                      int t) {
  SliceRing ring;
  ring.slice = k;
  ring.frame = t;
  const RegionMoments cavity = Moments(masks.cavity);
  ring.cavity_voxels = cavity.count;
  ring.myocardium_voxels = Moments(masks.myocardium).count;
  ring.has_cavity = cavity.count > 0;
  if (ring.has_cavity) {
    ring.cavity_centroid =
        volume.World(cavity.centroid.x(), cavity.centroid.y(), k);
    ring.closed = ring.myocardium_voxels > 0 &&
                  !ReachableFromBorder(masks.myocardium, masks.cavity);
    ring.myocardial_cover = MyocardialCover(masks);
  } else {
    ring.closed = ring.myocardium_voxels > 0;
  }
  return ring;
}

// The end of the stack the apex is at: the one farther from the
// cavity-weighted mean slice of frame 0 (the cavity is widest toward the
// base).
int ApexSlice(const std::vector<SliceRing>& rings, int nz) {
  int first = -1, last = -1;
  double weight = 0.0, sum = 0.0;
  for (int k = 0; k < nz; ++k) {
    const SliceRing& ring = rings[k];
    if (ring.cavity_voxels + ring.myocardium_voxels == 0) continue;
    if (first < 0) first = k;
    last = k;
    weight += ring.cavity_voxels;
    sum += ring.cavity_voxels * static_cast<double>(k);
  }
  if (first < 0 || weight == 0.0) return 0;
  const double mean = sum / weight;
  return mean - first > last - mean ? 0 : nz - 1;
}

// Marks the frame's slices from the apex to its base kept; returns the
// base, -1 when no slice holds a closed ring around a cavity.
int KeepApexToBase(std::vector<SliceRing>* rings, int nz, int t,
                   int apex_slice) {
  const int step = apex_slice == 0 ? 1 : -1;
  int base = -1;
  for (int k = apex_slice; k >= 0 && k < nz; k += step) {
    const SliceRing& ring = (*rings)[t * nz + k];
    if (ring.closed && ring.has_cavity) base = k;
  }
  if (base < 0) return -1;
  for (int k = apex_slice; k != base + step; k += step) {
    SliceRing& ring = (*rings)[t * nz + k];
    ring.kept = ring.cavity_voxels + ring.myocardium_voxels > 0;
  }
  const int closed_cavity = (*rings)[t * nz + base].cavity_voxels;
  for (int k = base + step; k >= 0 && k < nz; k += step) {
    SliceRing& ring = (*rings)[t * nz + k];
    if (ring.myocardial_cover < kPartialRingCover ||
        ring.cavity_voxels < kPartialRingArea * closed_cavity) {
      break;
    }
    ring.kept = ring.partial = true;
    base = k;
  }
  return base;
}

// The mask's boundary at slice position k (fractional: a slab's face);
// with `bordering`, only where it borders that mask's voxels.
void AddPoints(const LabelVolume& volume, const SliceMask& mask, double k,
               WallLayer layer, const SliceMask* bordering, Frame* frame,
               std::int64_t* next_id) {
  for (const Eigen::Vector2d& p : BoundaryPoints(mask)) {
    if (bordering && !BordersMyocardium(*bordering, p)) continue;
    frame->points.push_back(
        {(*next_id)++, volume.World(p.x(), p.y(), k), layer});
  }
}

// A slice's walls; the base's also at its slab's basal face, half a slice
// toward the base: its labels say the whole slab is LV, as the voxel count
// takes it, and without them the fitted cavity would end at the slice's
// centre, half a slab short (4 ml of the phantom's 106 at ED).
void AddWalls(const LabelVolume& volume, const Masks& masks, int k,
              double basal_face, bool partial, Frame* frame,
              std::int64_t* next_id) {
  const SliceMask* bordering = partial ? &masks.myocardium : nullptr;
  for (double at : {static_cast<double>(k), basal_face}) {
    if (std::isnan(at)) continue;
    AddPoints(volume, masks.cavity, at, WallLayer::kEndocardium, bordering,
              frame, next_id);
    AddPoints(volume, masks.lv, at, WallLayer::kEpicardium, bordering, frame,
              next_id);
  }
}

void AddRvInsertion(const LabelVolume& volume, const LabelMap& labels,
                    const Masks& masks, int k, MaskContours* out) {
  if (labels.rv < 0) return;
  const SliceMask rv =
      MaskOf(volume, k, 0, [&](std::int32_t v) { return v == labels.rv; });
  const auto ends =
      RvContactEnds(masks.myocardium, rv, Moments(masks.cavity).centroid,
                    volume.Spacing(0), volume.Spacing(1));
  if (!ends) return;
  out->rv_insertion.push_back(
      volume.World(ends->first.x(), ends->first.y(), k));
  out->rv_insertion.push_back(
      volume.World(ends->second.x(), ends->second.y(), k));
}

void Warn(const MisalignedSlice& slice, int num_frames, MaskContours* out) {
  char line[256];
  std::snprintf(line, sizeof(line),
                "slice %d: the LV cavity's centre lies up to %.1f mm off the "
                "line of its neighbours' in %zu of %d frames (a breath-hold "
                "shift?); its contours were moved back onto that line",
                slice.slice, slice.max_offset_mm, slice.frames.size(),
                num_frames);
  out->warnings.push_back(line);
}

// Moves each misaligned slice's contours in the frames it is off, and
// frame 0's RV insertion on it, back onto its neighbours' line, as biv-me
// corrects breath-hold shifts in-plane.  point_slice[t][i]: the slice of
// frame t's point i; rv_slice[i]: that of rv_insertion[i].
void MoveBack(const std::vector<std::vector<int>>& point_slice,
              const std::vector<int>& rv_slice, MaskContours* out) {
  for (const MisalignedSlice& slice : out->misaligned) {
    for (size_t n = 0; n < slice.frames.size(); ++n) {
      const int t = slice.frames[n];
      std::vector<DataPoint>& points = out->points.frames[t].points;
      for (size_t i = 0; i < points.size(); ++i) {
        if (point_slice[t][i] == slice.slice) {
          points[i].position -= slice.shifts[n];
        }
      }
      for (size_t i = 0; t == 0 && i < rv_slice.size(); ++i) {
        if (rv_slice[i] == slice.slice) out->rv_insertion[i] -= slice.shifts[n];
      }
    }
  }
}

}  // namespace

MaskContours ExtractMaskContours(const LabelVolume& volume,
                                 const LabelMap& labels) {
  CheckHasLv(volume, labels);
  const int nz = volume.nz, nt = volume.nt;
  MaskContours out;
  out.slice_thickness_mm = volume.Spacing(2);
  out.points.source = volume.source;
  out.points.contour_types = {"SAX_LV_ENDOCARDIAL", "SAX_LV_EPICARDIAL"};
  out.points.base_from_labels = true;
  for (int t = 0; t < nt; ++t) {
    for (int k = 0; k < nz; ++k) {
      out.rings.push_back(
          MeasureRing(volume, MasksOf(volume, labels, k, t), k, t));
    }
  }
  out.apex_slice = ApexSlice(out.rings, nz);
  std::int64_t next_id = 0;
  std::vector<std::vector<int>> point_slice(nt);
  std::vector<int> rv_slice;
  for (int t = 0; t < nt; ++t) {
    const int base = KeepApexToBase(&out.rings, nz, t, out.apex_slice);
    if (base < 0) {
      throw InputError(
          volume.source + ": frame " + std::to_string(t) +
          ": no slice where the myocardium (myo=" + std::to_string(labels.myo) +
          ") closes around the LV cavity (lv=" + std::to_string(labels.lv) +
          ")");
    }
    out.base_slice.push_back(base);
    Frame frame;
    frame.index = t;
    for (int k = 0; k < nz; ++k) {
      if (!out.rings[t * nz + k].kept) continue;
      const Masks masks = MasksOf(volume, labels, k, t);
      const double toward_base = out.apex_slice == 0 ? 0.5 : -0.5;
      const bool partial = out.rings[t * nz + k].partial;
      const bool closed_base = k == base && !partial;
      AddWalls(volume, masks, k, closed_base ? k + toward_base : std::nan(""),
               partial, &frame, &next_id);
      point_slice[t].resize(frame.points.size(), k);
      if (t == 0 && out.rings[k].closed) {
        AddRvInsertion(volume, labels, masks, k, &out);
        rv_slice.resize(out.rv_insertion.size(), k);
      }
    }
    out.points.frames.push_back(std::move(frame));
  }
  const Eigen::Vector3d normal = volume.world_from_voxel.col(2).head<3>();
  out.misaligned = FindMisalignedSlices(out.rings, nz, nt, normal);
  for (const MisalignedSlice& slice : out.misaligned) Warn(slice, nt, &out);
  MoveBack(point_slice, rv_slice, &out);
  return out;
}

}  // namespace pfdm
