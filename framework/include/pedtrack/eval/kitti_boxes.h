#pragma once
// The overlap (IoU) of KITTI's 3D boxes (pedtrack/kitti_calib.h) that KITTI's 3D tracking
// evaluation matches them by.
#include "pedtrack/eval/kitti_labels.h"

namespace pedtrack::eval {

using pedtrack::kittiAlpha;
using pedtrack::KittiCameraBox;
using pedtrack::kittiCorners;
using pedtrack::kittiImageBox;

/// Overlap of two boxes: the area of their footprints' intersection (the x-z plane) times the
/// overlap of their y extents, over the union of their volumes; 0 when either has no volume.
double kittiIou3d(const KittiCameraBox& a, const KittiCameraBox& b);

/// The footprints' IoU alone (bird's-eye view).
double kittiIouBev(const KittiCameraBox& a, const KittiCameraBox& b);

}  // namespace pedtrack::eval
