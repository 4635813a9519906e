#include <zdg/kernel/io/vol_io.hpp>

#include <zdg/arith/checked.hpp>
#include <zdg/kernel/io/input_file.hpp>
#include <zdg/kernel/io/output_files.hpp>

#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <limits>
#include <map>
#include <vector>

namespace zdg {

namespace {

constexpr int kMaxHeaderLines = 64;
constexpr std::size_t kMaxLineLength = 256;
constexpr std::int64_t kMaxExtent = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMaxCenter = std::int64_t{1} << 61;
// deflate never expands more than 1032:1 (zlib FAQ / RFC 1951 block structure).
constexpr std::uint64_t kMaxInflateRatio = 1032;

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw IoError(name + ": " + what);
}

struct Header {
  std::map<std::string, std::string> keys;
};

Header read_header(std::istream& in, const std::string& name) {
  Header h;
  for (int line = 1;; ++line) {
    if (line > kMaxHeaderLines)
      fail(name, "vol header longer than " + std::to_string(kMaxHeaderLines) + " lines");
    std::string text;
    bool newline = false;
    for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
      if (c == '\n') {
        newline = true;
        break;
      }
      if (text.size() >= kMaxLineLength) {
        fail(name + ":" + std::to_string(line),
             "vol header line longer than " + std::to_string(kMaxLineLength) + " bytes");
      }
      text.push_back(static_cast<char>(c));
    }
    if (!newline) {
      if (line == 1 && text.empty()) fail(name, "empty file (not a vol volume)");
      fail(name, "truncated vol header (no '.' line)");
    }
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text == ".") return h;
    const auto colon = text.find(':');
    if (colon == std::string::npos || colon == 0) {
      std::string shown;
      for (char c : text.substr(0, 40)) shown.push_back(c >= 32 && c < 127 ? c : '?');
      fail(name + ":" + std::to_string(line), "not a vol header line: '" + shown + "'");
    }
    std::string key = text.substr(0, colon), value = text.substr(colon + 1);
    while (!value.empty() && value.front() == ' ') value.erase(value.begin());
    while (!value.empty() && value.back() == ' ') value.pop_back();
    if (!h.keys.emplace(key, value).second)
      fail(name + ":" + std::to_string(line), "vol header key '" + key + "' appears twice");
  }
}

// The value of `key` as a decimal integer in [lo, hi] (range_text says which, in errors):
// the one range check each header number gets before any arithmetic uses it.
std::int64_t header_integer(const Header& h, const std::string& name, const std::string& key,
                            bool required, std::int64_t fallback, std::int64_t lo, std::int64_t hi,
                            const char* range_text) {
  const auto it = h.keys.find(key);
  if (it == h.keys.end()) {
    if (required) fail(name, "vol header has no '" + key + "' line");
    return fallback;
  }
  const std::string& v = it->second;
  const std::string shown = v.substr(0, 40);
  std::int64_t out = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
  const bool decimal = !v.empty() && end == v.data() + v.size();
  if (decimal && ec == std::errc::result_out_of_range)
    fail(name, "vol header '" + key + ": " + shown + "' is not in " + range_text);
  if (ec != std::errc() || !decimal)
    fail(name, "vol header '" + key + ": " + shown + "' is not a decimal integer");
  if (out < lo || out > hi)
    fail(name, "vol header '" + key + ": " + shown + "' is not in " + range_text);
  return out;
}

// The voxel bytes of a Version 3 payload: one zlib stream that inflates to exactly `need`
// bytes and ends at the end of the payload. Memory is taken as the bytes arrive
// (ArrivingBytes), not for the claim: a corrupt stream fails before its claim is allocated.
std::vector<std::uint8_t> inflate_exactly(const std::string& name, const std::string& packed,
                                          std::uint64_t need) {
  if (need > kMaxInflateRatio * packed.size() + 64) {
    fail(name, "vol header claims " + std::to_string(need) + " voxels but the " +
                   std::to_string(packed.size()) + " compressed bytes can hold at most " +
                   std::to_string(kMaxInflateRatio * packed.size() + 64) +
                   " (truncated file or wrong X, Y, Z)");
  }
  ArrivingBytes out(need);
  z_stream zs{};
  if (inflateInit(&zs) != Z_OK) fail(name, "zlib: cannot start decompression");
  struct End {
    z_stream* s;
    ~End() { inflateEnd(s); }
  } end{&zs};
  constexpr std::uint64_t kChunk = 1u << 30;
  std::uint64_t in_pos = 0;
  // Once the voxels are full, one spare byte detects a stream that inflates to more.
  std::uint8_t spare = 0;
  bool probing = false;
  int rc = Z_OK;
  for (;;) {
    if (zs.avail_in == 0 && in_pos < packed.size()) {
      const auto n = std::min<std::uint64_t>(kChunk, packed.size() - in_pos);
      zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data() + in_pos));
      zs.avail_in = static_cast<uInt>(n);
      in_pos += n;
    }
    std::span<std::uint8_t> room;
    if (!probing) room = out.room();
    if (room.empty()) {
      probing = true;
      zs.next_out = &spare;
      zs.avail_out = 1;
    } else {
      zs.next_out = room.data();
      zs.avail_out = static_cast<uInt>(room.size());
    }
    rc = inflate(&zs, Z_NO_FLUSH);
    if (probing && zs.avail_out == 0)
      fail(name, "zlib data inflates to more than X*Y*Z = " + std::to_string(need) + " bytes");
    if (!probing) out.arrived(room.size() - zs.avail_out);
    if (rc == Z_STREAM_END) break;
    if (rc == Z_BUF_ERROR && zs.avail_in == 0 && in_pos == packed.size()) {
      fail(name, "truncated zlib data: the stream stops after " + std::to_string(zs.total_out) +
                     " of the X*Y*Z = " + std::to_string(need) + " voxel bytes");
    }
    if (rc != Z_OK && rc != Z_BUF_ERROR) break;
  }
  if (rc == Z_DATA_ERROR || rc == Z_NEED_DICT) {
    fail(name, std::string("corrupt zlib data (") + (zs.msg != nullptr ? zs.msg : "bad stream") +
                   ") after " + std::to_string(zs.total_out) + " voxel bytes");
  }
  if (rc == Z_MEM_ERROR) fail(name, "zlib: out of memory");
  if (rc != Z_STREAM_END) fail(name, "zlib error " + std::to_string(rc));
  if (out.size() != need) {
    fail(name, "zlib data inflates to " + std::to_string(out.size()) +
                   " bytes, X*Y*Z = " + std::to_string(need) + " needed");
  }
  const std::uint64_t unused = zs.avail_in + (packed.size() - in_pos);
  if (unused != 0) fail(name, std::to_string(unused) + " bytes after the end of the zlib stream");
  return out.take();
}

std::string deflate_all(const std::vector<std::uint8_t>& raw) {
  z_stream zs{};
  if (deflateInit(&zs, Z_DEFAULT_COMPRESSION) != Z_OK)
    throw IoError("zlib: cannot start compression");
  struct End {
    z_stream* s;
    ~End() { deflateEnd(s); }
  } end{&zs};
  std::string out;
  constexpr std::size_t kChunk = std::size_t{1} << 30;
  std::size_t in_pos = 0;
  std::vector<char> buf(std::size_t{1} << 20);
  int rc = Z_OK;
  do {
    if (zs.avail_in == 0 && in_pos < raw.size()) {
      const std::size_t n = std::min(kChunk, raw.size() - in_pos);
      zs.next_in = const_cast<Bytef*>(raw.data() + in_pos);
      zs.avail_in = static_cast<uInt>(n);
      in_pos += n;
    }
    const int flush = in_pos == raw.size() ? Z_FINISH : Z_NO_FLUSH;
    zs.next_out = reinterpret_cast<Bytef*>(buf.data());
    zs.avail_out = static_cast<uInt>(buf.size());
    rc = deflate(&zs, flush);
    if (rc == Z_STREAM_ERROR) throw IoError("zlib: compression failed");
    out.append(buf.data(), buf.size() - zs.avail_out);
  } while (rc != Z_STREAM_END);
  return out;
}

} // namespace

Image<std::uint8_t> read_vol(std::istream& in, const std::string& name) {
  const Header h = read_header(in, name);
  const auto version_it = h.keys.find("Version");
  const std::string version = version_it == h.keys.end() ? "2" : version_it->second;
  if (version != "2" && version != "3")
    fail(name, "vol Version " + version.substr(0, 20) + " is not supported (2 or 3)");
  if (auto it = h.keys.find("Voxel-Endian"); it != h.keys.end() && it->second != "0")
    fail(name, "vol Voxel-Endian " + it->second.substr(0, 20) + " is not supported (0)");
  if (auto it = h.keys.find("Voxel-Size"); it != h.keys.end() && it->second != "1")
    fail(name, "vol Voxel-Size " + it->second.substr(0, 20) + " is not supported (1 byte)");
  const char* axis[3] = {"Z", "Y", "X"};
  std::int64_t size[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k)
    size[k] = header_integer(h, name, axis[k], true, 0, 1, kMaxExtent, "[1, 2^31 - 1]");
  std::vector<std::int64_t> lower(3);
  std::uint64_t need = 1;
  for (int k = 0; k < 3; ++k) {
    // Centers in [-2^61, 2^61] and sizes below 2^31: every coordinate of the volume lies in
    // (-2^62, 2^62), so that the difference of any two fits in 64 bits (checked all the same).
    const Int64 half = Int64(size[k] - 1) / Int64(2);
    const std::int64_t center =
        header_integer(h, name, std::string("Center-") + axis[k], false, half.value(), -kMaxCenter,
                       kMaxCenter, "[-2^61, 2^61]");
    const Int64 low = Int64(center) - half;
    (void)(low + Int64(size[k] - 1)); // the upper bound
    lower[static_cast<std::size_t>(k)] = low.value();
  }
  {
    std::uint64_t n = 0;
    if (__builtin_mul_overflow(static_cast<std::uint64_t>(size[0]),
                               static_cast<std::uint64_t>(size[1]), &n) ||
        __builtin_mul_overflow(n, static_cast<std::uint64_t>(size[2]), &n) ||
        n > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      fail(name, "vol size " + std::to_string(size[2]) + "x" + std::to_string(size[1]) + "x" +
                     std::to_string(size[0]) + " has more voxels than 2^63 - 1");
    }
    need = n;
  }
  const auto payload_start = in.tellg();
  in.seekg(0, std::ios::end);
  const auto payload_end = in.tellg();
  if (payload_start < 0 || payload_end < 0) fail(name, "cannot seek in the file");
  in.seekg(payload_start);
  const auto available = static_cast<std::uint64_t>(payload_end - payload_start);
  std::vector<std::uint8_t> voxels;
  if (version == "2") {
    if (available < need) {
      fail(name, "truncated voxel data: " + std::to_string(available) +
                     " bytes, X*Y*Z = " + std::to_string(need) + " needed");
    }
    if (available > need) {
      fail(name, std::to_string(available - need) + " bytes after the X*Y*Z = " +
                     std::to_string(need) + " voxel bytes (wrong X, Y, Z?)");
    }
    voxels.resize(static_cast<std::size_t>(need));
    in.read(reinterpret_cast<char*>(voxels.data()), static_cast<std::streamsize>(need));
    if (static_cast<std::uint64_t>(in.gcount()) != need) fail(name, "read error in voxel data");
  } else {
    std::string packed(static_cast<std::size_t>(available), '\0');
    in.read(packed.data(), static_cast<std::streamsize>(available));
    if (static_cast<std::uint64_t>(in.gcount()) != available) fail(name, "read error in zlib data");
    voxels = inflate_exactly(name, packed, need);
  }
  return Image<std::uint8_t>(Domain({size[0], size[1], size[2]}, lower), std::move(voxels));
}

Image<std::uint8_t> read_vol(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open for reading");
  return read_vol(in, path);
}

std::string vol_file_bytes(const Image<std::uint8_t>& image, int version) {
  if (image.dim() != 3) {
    throw InvalidArgument("vol holds 3D images, not " + std::to_string(image.dim()) + "-D ones");
  }
  if (version != 2 && version != 3)
    throw InvalidArgument("vol Version " + std::to_string(version) + " (2 or 3)");
  const Domain& d = image.domain();
  const char* axis[] = {"Z", "Y", "X"};
  for (int k = 0; k < 3; ++k) {
    if (d.extent(k) > kMaxExtent)
      throw InvalidArgument(std::string("vol size ") + axis[k] + " = " +
                            std::to_string(d.extent(k)) + " exceeds 2^31 - 1");
  }
  std::string out;
  for (int k = 2; k >= 0; --k) {
    // lower + (extent - 1) / 2 lies between lower and upper: no overflow.
    out += std::string("Center-") + axis[k] + ": " +
           std::to_string(d.lower(k) + (d.extent(k) - 1) / 2) + "\n";
  }
  for (int k = 2; k >= 0; --k)
    out += std::string(axis[k]) + ": " + std::to_string(d.extent(k)) + "\n";
  out += "Voxel-Size: 1\nAlpha-Color: 0\nVoxel-Endian: 0\nInt-Endian: 0123\nVersion: " +
         std::to_string(version) + "\n.\n";
  if (version == 2) {
    out.append(reinterpret_cast<const char*>(image.values().data()), image.values().size());
  } else {
    out += deflate_all(image.values());
  }
  return out;
}

void write_vol(const std::string& path, const Image<std::uint8_t>& image, int version) {
  write_file_atomically(path, vol_file_bytes(image, version));
}

void write_vol(const std::string& path, const Image<std::uint64_t>& image, int version) {
  std::vector<std::uint8_t> bytes(image.values().size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const auto v = image.values()[i];
    if (v > 255)
      throw InvalidArgument("value " + std::to_string(v) +
                            " does not fit a vol voxel (max 255); use .npy");
    bytes[i] = static_cast<std::uint8_t>(v);
  }
  write_vol(path, Image<std::uint8_t>(image.domain(), std::move(bytes)), version);
}

} // namespace zdg
