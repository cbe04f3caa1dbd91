#include "vision/jpeg_codec.hpp"

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

// jpeglib.h wants FILE and size_t declared before it.
#include <jpeglib.h>

#if !defined(JCS_EXTENSIONS)
#error "vision/jpeg_codec.cpp needs libjpeg-turbo (JCS_EXT_BGR): Debian's libjpeg-dev"
#endif

namespace argus::vision {

namespace {

// libjpeg's own error_exit ends the process. Ours jumps back to the call, which throws once
// no libjpeg frame is left between it and the throw: an exception may not cross C code.
struct error_manager {
  jpeg_error_mgr library;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void jump_back(j_common_ptr info) {
  auto* errors = reinterpret_cast<error_manager*>(info->err);
  (*info->err->format_message)(info, errors->message);
  std::longjmp(errors->back, 1);
}

void route_errors(error_manager& errors) {
  jpeg_std_error(&errors.library);
  errors.library.error_exit = jump_back;
  errors.message[0] = '\0';
}

// The library's calls in a frame of their own whose locals are plain data, so the jump skips
// no destructor. False when the library failed (errors.message).
bool encode_into(const cv::Mat& bgr, int quality, error_manager& errors,
                 std::vector<std::uint8_t>& encoded) {
  jpeg_compress_struct info{};
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  info.err = &errors.library;
  if (setjmp(errors.back) != 0) {
    jpeg_destroy_compress(&info);
    std::free(buffer);
    return false;
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = static_cast<JDIMENSION>(bgr.cols);
  info.image_height = static_cast<JDIMENSION>(bgr.rows);
  info.input_components = 3;
  info.in_color_space = JCS_EXT_BGR;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, std::clamp(quality, 1, 100), TRUE);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    // libjpeg's row type is not const; it only reads input rows.
    JSAMPROW row =
        const_cast<JSAMPROW>(bgr.ptr<unsigned char>(static_cast<int>(info.next_scanline)));
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  encoded.assign(buffer, buffer + size);
  std::free(buffer);
  return true;
}

// As encode_into; `out` belongs to the caller.
bool decode_into(std::span<const std::uint8_t> encoded, error_manager& errors, cv::Mat& out) {
  jpeg_decompress_struct info{};
  info.err = &errors.library;
  if (setjmp(errors.back) != 0) {
    jpeg_destroy_decompress(&info);
    return false;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, encoded.data(), static_cast<unsigned long>(encoded.size()));
  jpeg_read_header(&info, TRUE);
  info.out_color_space = JCS_EXT_BGR;
  jpeg_start_decompress(&info);
  out.create(static_cast<int>(info.output_height), static_cast<int>(info.output_width), CV_8UC3);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out.ptr<unsigned char>(static_cast<int>(info.output_scanline));
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return true;
}

}  // namespace

void encode_jpeg(const cv::Mat& bgr, int quality, std::vector<std::uint8_t>& encoded) {
  if (bgr.type() != CV_8UC3 || bgr.empty()) {
    throw std::invalid_argument("encode_jpeg: expected a non-empty 8-bit BGR image");
  }
  error_manager errors{};
  route_errors(errors);
  if (!encode_into(bgr, quality, errors, encoded)) {
    throw std::runtime_error(std::string("encode_jpeg: ") + errors.message);
  }
}

cv::Mat decode_jpeg(std::span<const std::uint8_t> encoded) {
  error_manager errors{};
  route_errors(errors);
  cv::Mat out;
  if (!decode_into(encoded, errors, out)) {
    throw std::runtime_error(std::string("decode_jpeg: ") + errors.message);
  }
  return out;
}

}  // namespace argus::vision
