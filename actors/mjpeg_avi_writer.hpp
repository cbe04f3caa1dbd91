#pragma once

// A Motion-JPEG video in an AVI file (RIFF: header list, frame list, index), each frame a JPEG
// from vision::encode_jpeg (the bytes cv::imencode writes). Written here rather than through
// cv::VideoWriter so that `argus` does not load OpenCV's video I/O module, which pulls in about a
// hundred shared libraries (FFmpeg, GStreamer) that start-up would pay for on every command.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "opencv2/core.hpp"

namespace argus::actors {

/// Writes BGR frames of one size as an MJPG AVI at a fixed frame rate; the file is complete
/// after close() (or destruction).
class mjpeg_avi_writer {
 public:
  /// Opens `path` for frames of `size` at `frames_per_second`, JPEG quality `quality` (0-100).
  /// Throws std::runtime_error if the file cannot be written.
  mjpeg_avi_writer(const std::filesystem::path& path, double frames_per_second, cv::Size size,
                   int quality = 95);
  ~mjpeg_avi_writer();
  mjpeg_avi_writer(const mjpeg_avi_writer&) = delete;
  mjpeg_avi_writer& operator=(const mjpeg_avi_writer&) = delete;

  /// Appends one CV_8UC3 frame of the writer's size.
  void write(const cv::Mat& bgr);

  /// Writes the index and the sizes and frame count in the headers; no write() after.
  void close();

 private:
  struct index_entry {
    std::uint32_t offset;
    std::uint32_t size;
  };

  std::ofstream out_;
  cv::Size size_;
  int quality_;
  double frames_per_second_;
  std::vector<index_entry> index_;
  std::vector<unsigned char> jpeg_;
  std::uint32_t largest_frame_ = 0;
  bool open_ = false;
};

}  // namespace argus::actors
