#include "image_output.h"

#include <opencv2/imgcodecs.hpp>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack::render {

void writePng(const std::string& path, const cv::Mat& img) {
  bool ok = false;
  std::string why = "cv::imwrite failed";
  try {
    ok = cv::imwrite(path, img);
  } catch (const cv::Exception& e) {
    why = oneLine(e.what());
  }
  if (!ok) throw DataError(path + ": cannot write PNG (" + why + ")");
}

Mp4Writer::Mp4Writer(const std::string& path, double fps, int size) : path_(path) {
  // 'mp4v' (MPEG-4 part 2) is what Debian's FFmpeg build encodes without extra licences; H.264
  // encoders are often missing, and a failure to open must be reported, not produce no file.
  try {
    writer_.open(path, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps,
                 cv::Size(size, size), true);
  } catch (const cv::Exception&) {
  }
  if (!writer_.isOpened())
    throw DataError(path +
                    ": cannot open a video writer with codec 'mp4v' (OpenCV FFmpeg backend; is "
                    "libopencv-videoio built with FFmpeg, and the folder writable?)");
}

void Mp4Writer::write(const cv::Mat& img) {
  writer_.write(img);
  ++frames_;
}

void Mp4Writer::close() {
  writer_.release();
}

}  // namespace pedtrack::render
