#include "actors/mjpeg_avi_writer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vision/jpeg_codec.hpp"

namespace argus::actors {
namespace {

// Byte offsets in the file of the fields close() fills in (the layout written below).
constexpr std::streamoff riff_size_at = 4;
constexpr std::streamoff total_frames_at = 48;
constexpr std::streamoff suggested_buffer_at = 60;
constexpr std::streamoff stream_length_at = 140;
constexpr std::streamoff stream_buffer_at = 144;
constexpr std::streamoff movi_size_at = 216;
// Where the 'movi' list's type starts: index offsets count from here.
constexpr std::streamoff movi_start = 220;

void put32(std::ofstream& out, std::uint32_t v) {
  const char bytes[4] = {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff),
                         static_cast<char>((v >> 16) & 0xff), static_cast<char>((v >> 24) & 0xff)};
  out.write(bytes, 4);
}

void put16(std::ofstream& out, std::uint16_t v) {
  const char bytes[2] = {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff)};
  out.write(bytes, 2);
}

void put_code(std::ofstream& out, const char (&code)[5]) {
  out.write(code, 4);
}

void put32_at(std::ofstream& out, std::streamoff at, std::uint32_t v) {
  out.seekp(at);
  put32(out, v);
}

}  // namespace

mjpeg_avi_writer::mjpeg_avi_writer(const std::filesystem::path& path, double frames_per_second,
                                   cv::Size size, int quality)
    : out_(path, std::ios::binary | std::ios::trunc),
      size_(size),
      quality_(quality),
      frames_per_second_(frames_per_second) {
  if (!out_ || size.width <= 0 || size.height <= 0 || !(frames_per_second > 0.0))
    throw std::runtime_error("cannot write " + path.string());
  const auto width = static_cast<std::uint32_t>(size.width);
  const auto height = static_cast<std::uint32_t>(size.height);
  // The rate as an exact fraction where it is one (15 fps: 15 / 1), else in millionths.
  const bool whole = std::abs(frames_per_second - std::round(frames_per_second)) < 1e-9;
  const auto scale = whole ? 1u : 1000000u;
  const auto rate = static_cast<std::uint32_t>(std::lround(frames_per_second * scale));
  put_code(out_, "RIFF");
  put32(out_, 0);  // riff_size_at
  put_code(out_, "AVI ");
  put_code(out_, "LIST");
  put32(out_, 192);  // 'hdrl' + avih (8 + 56) + strl list (8 + 116)
  put_code(out_, "hdrl");
  put_code(out_, "avih");
  put32(out_, 56);
  put32(out_, static_cast<std::uint32_t>(std::lround(1e6 / frames_per_second)));
  put32(out_, 0);     // max bytes per second
  put32(out_, 0);     // padding granularity
  put32(out_, 0x10);  // AVIF_HASINDEX
  put32(out_, 0);     // total frames: total_frames_at
  put32(out_, 0);     // initial frames
  put32(out_, 1);     // streams
  put32(out_, 0);     // suggested buffer size: suggested_buffer_at
  put32(out_, width);
  put32(out_, height);
  for (int i = 0; i < 4; ++i) put32(out_, 0);
  put_code(out_, "LIST");
  put32(out_, 116);  // 'strl' + strh (8 + 56) + strf (8 + 40)
  put_code(out_, "strl");
  put_code(out_, "strh");
  put32(out_, 56);
  put_code(out_, "vids");
  put_code(out_, "MJPG");
  put32(out_, 0);  // flags
  put16(out_, 0);  // priority
  put16(out_, 0);  // language
  put32(out_, 0);  // initial frames
  put32(out_, scale);
  put32(out_, rate);
  put32(out_, 0);           // start
  put32(out_, 0);           // length: stream_length_at
  put32(out_, 0);           // suggested buffer size: stream_buffer_at
  put32(out_, 0xffffffff);  // quality: default
  put32(out_, 0);           // sample size: varies
  put16(out_, 0);
  put16(out_, 0);
  put16(out_, static_cast<std::uint16_t>(width));
  put16(out_, static_cast<std::uint16_t>(height));
  put_code(out_, "strf");
  put32(out_, 40);
  put32(out_, 40);
  put32(out_, width);
  put32(out_, height);
  put16(out_, 1);   // planes
  put16(out_, 24);  // bits per pixel
  put_code(out_, "MJPG");
  put32(out_, width * height * 3);
  for (int i = 0; i < 4; ++i) put32(out_, 0);
  put_code(out_, "LIST");
  put32(out_, 0);  // movi_size_at
  put_code(out_, "movi");
  open_ = true;
}

mjpeg_avi_writer::~mjpeg_avi_writer() {
  try {
    close();
  } catch (...) {
    // nop: a destructor does not throw; the file is left incomplete
  }
}

void mjpeg_avi_writer::write(const cv::Mat& bgr) {
  CV_Assert(open_ && bgr.type() == CV_8UC3 && bgr.size() == size_);
  vision::encode_jpeg(bgr, quality_, jpeg_);
  const auto size = static_cast<std::uint32_t>(jpeg_.size());
  index_.push_back({static_cast<std::uint32_t>(out_.tellp() - movi_start), size});
  largest_frame_ = std::max(largest_frame_, size);
  put_code(out_, "00dc");
  put32(out_, size);
  out_.write(reinterpret_cast<const char*>(jpeg_.data()), static_cast<std::streamsize>(size));
  if (size % 2 != 0) out_.put('\0');  // chunks are padded to even sizes
}

void mjpeg_avi_writer::close() {
  if (!open_) return;
  open_ = false;
  const auto movi_end = static_cast<std::uint32_t>(out_.tellp());
  put_code(out_, "idx1");
  put32(out_, static_cast<std::uint32_t>(index_.size() * 16));
  for (const auto& entry : index_) {
    put_code(out_, "00dc");
    put32(out_, 0x10);  // AVIIF_KEYFRAME
    put32(out_, entry.offset);
    put32(out_, entry.size);
  }
  const auto end = static_cast<std::uint32_t>(out_.tellp());
  const auto frames = static_cast<std::uint32_t>(index_.size());
  put32_at(out_, riff_size_at, end - 8);
  put32_at(out_, total_frames_at, frames);
  put32_at(out_, suggested_buffer_at, largest_frame_ + 8);
  put32_at(out_, stream_length_at, frames);
  put32_at(out_, stream_buffer_at, largest_frame_ + 8);
  put32_at(out_, movi_size_at, movi_end - static_cast<std::uint32_t>(movi_start));
  out_.close();
  if (!out_) throw std::runtime_error("video: writing the file failed");
}

}  // namespace argus::actors
