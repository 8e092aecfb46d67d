#pragma once
// KITTI's calibration files and 3D boxes as its label and results files write them (rectified
// camera frame: x right, y down, z forward; x y z the bottom centre; rotation_y about y): the
// Velodyne-to-camera transform, a box's corners, its image box through P2 and its observation
// angle. The `detections` source, `pedtrack eval` and `pedtrack render` share them.
#include <Eigen/Core>
#include <array>
#include <string>

namespace pedtrack {

/// One calibration file (`calib/NNNNNN.txt` or `calib/SSSS.txt`): the left colour camera's
/// projection P2, the rectifying rotation R0_rect and the Velodyne-to-camera transform (the
/// tracking benchmark's own spelling, `R_rect` and `Tr_velo_cam`, is read too).
struct KittiCalib {
  Eigen::Matrix<double, 3, 4> P2 = Eigen::Matrix<double, 3, 4>::Zero();
  Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 3, 4> velo_to_cam = Eigen::Matrix<double, 3, 4>::Zero();
  /// The colour images' size (px): KITTI's are 1,242 × 375 (a few drives 1,224–1,241 wide).
  double image_width = 1242, image_height = 375;

  /// A point of the rectified camera frame (x right, y down, z forward) in the Velodyne frame.
  Eigen::Vector3d veloFromRect(const Eigen::Vector3d& rect) const;
  /// A Velodyne-frame point in the rectified camera frame.
  Eigen::Vector3d rectFromVelo(const Eigen::Vector3d& velo) const;
  /// Whether a Velodyne-frame point is in front of the camera and projects inside the image,
  /// whose width is taken as twice P2's principal point (KITTI's images are 1,224-1,242 px).
  bool inCameraView(const Eigen::Vector3d& velo) const;
};

/// Reads a calibration file; throws DataError naming the file and the key at fault.
KittiCalib readKittiCalib(const std::string& path);

struct KittiCameraBox {
  double h = 0, w = 0, l = 0;  ///< m: height, width, length (l along the heading)
  double x = 0, y = 0, z = 0;  ///< m: the bottom centre, rectified camera frame
  double ry = 0;               ///< rad: rotation_y, about the camera's y axis
};

/// The eight corners: the bottom four (y = box y) then the top four (y − h), each set in turn
/// front-left, front-right, back-right, back-left of the box's own (l, w) axes.
std::array<Eigen::Vector3d, 8> kittiCorners(const KittiCameraBox& b);

/// The box's image rectangle (x1, y1, x2, y2, pixels) through P2, clipped to the image. False
/// when a corner is behind the camera (z ≤ 0.1 m) or the box lies wholly beside the image.
bool kittiImageBox(const KittiCalib& c, const KittiCameraBox& b, std::array<double, 4>& xyxy);

/// KITTI's observation angle: rotation_y minus the bearing of the box centre, in (−π, π].
double kittiAlpha(const KittiCameraBox& b);

/// KITTI's layout, DATA/<folder>/SSSS.txt beside DATA/calib/SSSS.txt (labels, a detector's
/// output): the calibration file of `file`, empty when there is none.
std::string kittiCalibBeside(const std::string& file);

/// rotation_y turns a box about the camera's y (down) axis from the camera's x (right): in the
/// Velodyne's frame (x forward, z up) its heading is −rotation_y − π/2, in (−π, π].
double veloYawFromRotationY(double rotation_y);
/// The inverse: rotation_y = −yaw − π/2, in (−π, π].
double rotationYFromVeloYaw(double yaw);

}  // namespace pedtrack
