#pragma once

// JPEG through libjpeg-turbo itself, BGR in and out. cv::imencode and cv::imdecode call the
// same library with the same settings (baseline, 4:2:0, the accurate DCT, fancy upsampling),
// so the bytes and the pixels are the same; but OpenCV's code around the codec (its own
// row-by-row colour conversion and copies) cost as much as the codec in a pixel run's profile
// (bench/RESULTS.md, "The JPEG round trip without OpenCV's row copies").

#include <cstdint>
#include <span>
#include <vector>

#include "opencv2/core.hpp"

namespace argus::vision {

/// Encodes 8-bit BGR `bgr` (any size, continuous or not) at `quality` (clamped to 1-100) into
/// `encoded` (replaced), byte for byte what cv::imencode(".jpg", bgr, encoded,
/// {IMWRITE_JPEG_QUALITY, quality}) writes. Throws std::invalid_argument for another type or
/// an empty image, std::runtime_error when the library fails.
void encode_jpeg(const cv::Mat& bgr, int quality, std::vector<std::uint8_t>& encoded);

/// Decodes a JPEG to 8-bit BGR, the pixels cv::imdecode(encoded, IMREAD_COLOR) gives.
/// Throws std::runtime_error, naming what the library said, for bytes that are not a JPEG.
cv::Mat decode_jpeg(std::span<const std::uint8_t> encoded);

}  // namespace argus::vision
