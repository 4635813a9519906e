#include <zdg/kernel/vol_io.hpp>

#include <zdg/kernel/output_files.hpp>

#include <fstream>
#include <iterator>
#include <map>

namespace zdg {

Image<std::uint8_t> read_vol(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open for reading");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (data.empty()) throw IoError(path + ": empty file (not a vol volume)");
  std::map<std::string, std::string> keys;
  std::size_t pos = 0;
  int line = 0;
  bool ended = false;
  while (pos < data.size()) {
    ++line;
    auto nl = data.find('\n', pos);
    if (nl == std::string::npos) break;
    std::string text = data.substr(pos, nl - pos);
    pos = nl + 1;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text == ".") {
      ended = true;
      break;
    }
    auto colon = text.find(':');
    if (colon == std::string::npos || line > 64) {
      throw IoError(path + ":" + std::to_string(line) + ": not a vol header line: '" +
                    text.substr(0, 40) + "'");
    }
    std::string v = text.substr(colon + 1);
    while (!v.empty() && v.front() == ' ') v.erase(v.begin());
    keys[text.substr(0, colon)] = v;
  }
  if (!ended) throw IoError(path + ": truncated vol header (no '.' line)");
  auto integer = [&](const std::string& k, bool required, std::int64_t dflt) {
    auto it = keys.find(k);
    if (it == keys.end()) {
      if (required) throw IoError(path + ": vol header has no '" + k + "' line");
      return dflt;
    }
    try {
      std::size_t used = 0;
      long long v = std::stoll(it->second, &used);
      if (used != it->second.size()) throw std::invalid_argument("trailing");
      return static_cast<std::int64_t>(v);
    } catch (const std::exception&) {
      throw IoError(path + ": vol header '" + k + ": " + it->second + "' is not an integer");
    }
  };
  if (keys.count("Version") != 0 && keys["Version"] != "2") {
    throw IoError(path + ": vol Version " + keys["Version"] +
                  " (compressed) is not supported, only Version 2");
  }
  if (keys.count("Voxel-Endian") != 0 && keys["Voxel-Endian"] != "0") {
    throw IoError(path + ": Voxel-Endian " + keys["Voxel-Endian"] + " is not supported");
  }
  std::int64_t x = integer("X", true, 0), y = integer("Y", true, 0), z = integer("Z", true, 0);
  if (x < 1 || y < 1 || z < 1 || x > (1 << 20) || y > (1 << 20) || z > (1 << 20)) {
    throw IoError(path + ": bad vol size " + std::to_string(x) + "x" + std::to_string(y) + "x" +
                  std::to_string(z));
  }
  std::vector<std::int64_t> lower{integer("Center-Z", false, (z - 1) / 2) - (z - 1) / 2,
                                  integer("Center-Y", false, (y - 1) / 2) - (y - 1) / 2,
                                  integer("Center-X", false, (x - 1) / 2) - (x - 1) / 2};
  std::size_t need = static_cast<std::size_t>(x * y * z);
  if (data.size() - pos < need) {
    throw IoError(path + ": truncated voxel data: " + std::to_string(data.size() - pos) +
                  " bytes, " + std::to_string(need) + " needed");
  }
  Image<std::uint8_t> img(Domain({z, y, x}, lower));
  for (std::size_t i = 0; i < need; ++i) img.values()[i] = static_cast<std::uint8_t>(data[pos + i]);
  return img;
}

void write_vol(const std::string& path, const Image<std::uint64_t>& image) {
  if (image.dim() != 3) {
    throw InvalidArgument("vol holds 3D images, not " + std::to_string(image.dim()) + "-D ones");
  }
  const Domain& d = image.domain();
  std::string out;
  const char* axis[] = {"Z", "Y", "X"};
  for (int k = 2; k >= 0; --k) {
    out += std::string("Center-") + axis[k] + ": " +
           std::to_string(d.lower(k) + (d.extent(k) - 1) / 2) + "\n";
  }
  for (int k = 2; k >= 0; --k)
    out += std::string(axis[k]) + ": " + std::to_string(d.extent(k)) + "\n";
  out += "Voxel-Size: 1\nAlpha-Color: 0\nVoxel-Endian: 0\nInt-Endian: 0123\nVersion: 2\n.\n";
  for (auto v : image.values()) {
    if (v > 255)
      throw InvalidArgument("value " + std::to_string(v) +
                            " does not fit a vol voxel (max 255); use .npy");
    out.push_back(static_cast<char>(v));
  }
  write_file_atomically(path, out);
}

} // namespace zdg
