#pragma once
// Writing pictures: a PNG file, or an MP4 video through OpenCV's FFmpeg backend.
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>

namespace pedtrack::render {

/// Writes `img` as PNG. Throws DataError naming the file when it cannot be written.
void writePng(const std::string& path, const cv::Mat& img);

/// An MP4 video ('mp4v' codec) of square frames.
class Mp4Writer {
 public:
  /// Throws DataError naming the file and codec when no writer can be opened.
  Mp4Writer(const std::string& path, double fps, int size);
  void write(const cv::Mat& img);
  /// Finishes the file (also done by the destructor).
  void close();
  std::size_t frames() const { return frames_; }

 private:
  std::string path_;
  cv::VideoWriter writer_;
  std::size_t frames_ = 0;
};

}  // namespace pedtrack::render
