#include <zdg/kernel/io/mesh_io.hpp>

#include <zdg/arith/error.hpp>
#include <zdg/kernel/io/output_files.hpp>
#include <zdg/kernel/parallel/parallel_for.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <future>
#include <limits>
#include <vector>

namespace zdg {

namespace {

// A file written through an OutputSet staging file: finish() flushes, checks and renames.
class StagedFile {
public:
  explicit StagedFile(const std::string& path) : path_(path), set_(Existing::replace) {
    staging_ = set_.add(path);
    f_ = std::fopen(staging_.c_str(), "wb");
    if (f_ == nullptr) throw IoError(path + ": cannot write (" + std::strerror(errno) + ")");
    std::setvbuf(f_, nullptr, _IOFBF, std::size_t{1} << 22);
  }
  ~StagedFile() {
    if (f_ != nullptr) std::fclose(f_);
  }
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  void write(const void* data, std::size_t n) {
    if (n != 0 && std::fwrite(data, 1, n, f_) != n) fail();
  }
  void write(const std::string& s) { write(s.data(), s.size()); }
  void finish() {
    const bool bad = std::fflush(f_) != 0 || std::ferror(f_) != 0;
    const bool closed = std::fclose(f_) == 0;
    f_ = nullptr;
    if (bad || !closed) fail();
    set_.commit();
  }

private:
  [[noreturn]] void fail() { throw IoError(path_ + ": write failed (disk full?)"); }
  std::string path_;
  OutputSet set_;
  std::filesystem::path staging_;
  std::FILE* f_ = nullptr;
};

constexpr std::int64_t kBlock = std::int64_t{1} << 18;

// Formats items [0, n) with fn(i, out) in blocks of kBlock, each block split among the
// threads, and writes the text in order.
void write_text_items(StagedFile& file, std::int64_t n, unsigned threads,
                      const std::function<void(std::int64_t, std::string&)>& fn) {
  const std::int64_t t = worker_count(threads, kBlock);
  std::vector<std::string> parts(static_cast<std::size_t>(t));
  for (std::int64_t b = 0; b < n; b += kBlock) {
    const std::int64_t len = std::min(n - b, kBlock);
    parallel_for(t, static_cast<unsigned>(t), [&](std::int64_t k) {
      const std::int64_t lo = b + len * k / t, hi = b + len * (k + 1) / t; // len t < 2^26
      std::string out;
      out.reserve(static_cast<std::size_t>(hi - lo) * 40);
      for (std::int64_t i = lo; i < hi; ++i) fn(i, out);
      parts[static_cast<std::size_t>(k)] = std::move(out);
    });
    for (auto& p : parts) {
      file.write(p);
      p.clear();
    }
  }
}

void append_float(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, static_cast<float>(v));
  out.append(buf, r.ptr);
}

void append_int(std::string& out, std::int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// Three floats at out (little-endian host); returns the end.
char* put(char* out, float x, float y, float z) {
  const float v[3] = {x, y, z};
  std::memcpy(out, v, sizeof v);
  return out + sizeof v;
}

// Writes n records of `size` bytes each, record i made by fill(i, out), in blocks of 2^18
// records: each block is formatted in parallel while the previous one is being written (the
// write is the kernel's copy into the page cache, as long as the formatting).
template <class Fill>
void write_records(StagedFile& file, std::int64_t n, std::size_t size, unsigned threads,
                   Fill&& fill) {
  constexpr std::int64_t block = std::int64_t{1} << 18;
  const auto cap = static_cast<std::size_t>(std::min(n, block)) * size;
  std::vector<char> buf[2] = {std::vector<char>(cap), std::vector<char>(n > block ? cap : 0)};
  std::future<void> writing;
  for (std::int64_t b = 0, k = 0; b < n; b += block, ++k) {
    const std::int64_t len = std::min(n - b, block);
    char* out = buf[k % 2].data();
    parallel_chunks(len, threads, [&](std::int64_t lo, std::int64_t hi) {
      for (std::int64_t i = lo; i < hi; ++i) fill(b + i, out + std::size_t(i) * size);
    });
    if (writing.valid()) writing.get(); // rethrows a failed write
    writing = std::async(std::launch::async, [&file, out, len, size] {
      file.write(out, static_cast<std::size_t>(len) * size);
    });
  }
  if (writing.valid()) writing.get();
}

} // namespace

std::string ply_property_name(const std::string& field) {
  std::string s = field.empty() ? std::string("field") : field;
  for (char& c : s) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) c = '_';
  }
  return s;
}

MeshFormat mesh_format_of(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (e == ".ply") return MeshFormat::ply;
  if (e == ".obj") return MeshFormat::obj;
  if (e == ".off") return MeshFormat::off;
  throw IoError(path + ": unknown mesh format '" + e + "' (.ply, .obj or .off)");
}

void write_ply(const std::string& path, const PolygonMesh& mesh, unsigned threads) {
  mesh.validate();
  const std::int64_t nv = mesh.vertex_count(), nf = mesh.face_count();
  if (static_cast<std::uint64_t>(nv) > std::numeric_limits<std::uint32_t>::max())
    throw InvalidArgument(path + ": " + std::to_string(nv) +
                          " vertices exceed the 32-bit indices of PLY; write .obj or .off");
  if (mesh.face_size > 255)
    throw InvalidArgument(path + ": faces of " + std::to_string(mesh.face_size) +
                          " vertices exceed PLY's uchar count");
  const bool wide = nv > std::numeric_limits<std::int32_t>::max();
  const bool vn = !mesh.vertex_normals.empty(), fnorm = !mesh.face_normals.empty();
  std::string h = "ply\nformat binary_little_endian 1.0\ncomment written by zdg\n";
  if (!mesh.face_scalars.empty()) {
    h += "comment face fields:";
    for (const auto& [name, values] : mesh.face_scalars) {
      h += ' ';
      for (char c : name) h.push_back(c == '\n' || c == '\r' ? ' ' : c);
    }
    h += '\n';
  }
  h += "element vertex " + std::to_string(nv) + "\nproperty float x\nproperty float y\n" +
       "property float z\n";
  if (vn) h += "property float nx\nproperty float ny\nproperty float nz\n";
  h += "element face " + std::to_string(nf) + "\nproperty list uchar " + (wide ? "uint" : "int") +
       " vertex_indices\n";
  if (fnorm) h += "property float nx\nproperty float ny\nproperty float nz\n";
  std::vector<std::string> used;
  for (const auto& [name, values] : mesh.face_scalars) {
    std::string p = ply_property_name(name);
    const std::string base = p;
    for (int k = 2; std::find(used.begin(), used.end(), p) != used.end() || p == "nx" ||
                    p == "ny" || p == "nz" || p == "vertex_indices";
         ++k)
      p = base + "_" + std::to_string(k);
    used.push_back(p);
    h += "property float " + p + "\n";
  }
  h += "end_header\n";
  StagedFile file(path);
  file.write(h);
  const std::size_t vrec = vn ? 24 : 12;
  write_records(file, nv, vrec, threads, [&](std::int64_t i, char* out) {
    const auto& p = mesh.vertices[static_cast<std::size_t>(i)];
    out = put(out, static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
    if (vn) {
      const auto& n = mesh.vertex_normals[static_cast<std::size_t>(i)];
      put(out, static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z));
    }
  });
  const auto fs = static_cast<std::size_t>(mesh.face_size);
  const std::size_t frec = 1 + 4 * fs + (fnorm ? 12 : 0) + 4 * mesh.face_scalars.size();
  write_records(file, nf, frec, threads, [&](std::int64_t f, char* out) {
    *out++ = static_cast<char>(static_cast<std::uint8_t>(fs));
    const std::int64_t* idx = mesh.indices.data() + static_cast<std::size_t>(f) * fs;
    for (std::size_t k = 0; k < fs; ++k) {
      // validate() put every index in [0, nv), and nv < 2^32: the low 32 bits are the index,
      // read as int32 or uint32 (wide) alike.
      const auto v = static_cast<std::uint32_t>(idx[k]);
      std::memcpy(out, &v, 4);
      out += 4;
    }
    if (fnorm) {
      const auto& n = mesh.face_normals[static_cast<std::size_t>(f)];
      out = put(out, static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z));
    }
    for (const auto& [name, values] : mesh.face_scalars) {
      const auto v = static_cast<float>(values[static_cast<std::size_t>(f)]);
      std::memcpy(out, &v, 4);
      out += 4;
    }
  });
  file.finish();
}

void write_obj(const std::string& path, const PolygonMesh& mesh, unsigned threads) {
  mesh.validate();
  const bool vn = !mesh.vertex_normals.empty();
  StagedFile file(path);
  std::string h = "# written by zdg: " + std::to_string(mesh.vertex_count()) + " vertices, " +
                  std::to_string(mesh.face_count()) + " faces\n";
  for (const auto& [name, values] : mesh.face_scalars) {
    h += "# face field not stored in OBJ (write .ply): ";
    for (char c : name) h.push_back(c == '\n' || c == '\r' ? ' ' : c);
    h += '\n';
  }
  file.write(h);
  write_text_items(file, mesh.vertex_count(), threads, [&](std::int64_t i, std::string& out) {
    const auto& p = mesh.vertices[static_cast<std::size_t>(i)];
    out += "v ";
    append_float(out, p.x);
    out += ' ';
    append_float(out, p.y);
    out += ' ';
    append_float(out, p.z);
    out += '\n';
  });
  if (vn) {
    write_text_items(file, mesh.vertex_count(), threads, [&](std::int64_t i, std::string& out) {
      const auto& n = mesh.vertex_normals[static_cast<std::size_t>(i)];
      out += "vn ";
      append_float(out, n.x);
      out += ' ';
      append_float(out, n.y);
      out += ' ';
      append_float(out, n.z);
      out += '\n';
    });
  }
  write_text_items(file, mesh.face_count(), threads, [&](std::int64_t f, std::string& out) {
    out += 'f';
    for (const auto i : mesh.face(f)) {
      out += ' ';
      append_int(out, i + 1);
      if (vn) {
        out += "//";
        append_int(out, i + 1);
      }
    }
    out += '\n';
  });
  file.finish();
}

void write_off(const std::string& path, const PolygonMesh& mesh, unsigned threads) {
  mesh.validate();
  StagedFile file(path);
  file.write("OFF\n" + std::to_string(mesh.vertex_count()) + " " +
             std::to_string(mesh.face_count()) + " 0\n");
  write_text_items(file, mesh.vertex_count(), threads, [&](std::int64_t i, std::string& out) {
    const auto& p = mesh.vertices[static_cast<std::size_t>(i)];
    append_float(out, p.x);
    out += ' ';
    append_float(out, p.y);
    out += ' ';
    append_float(out, p.z);
    out += '\n';
  });
  write_text_items(file, mesh.face_count(), threads, [&](std::int64_t f, std::string& out) {
    append_int(out, mesh.face_size);
    for (const auto i : mesh.face(f)) {
      out += ' ';
      append_int(out, i);
    }
    out += '\n';
  });
  file.finish();
}

void write_mesh(const std::string& path, const PolygonMesh& mesh, std::optional<MeshFormat> format,
                unsigned threads) {
  switch (format ? *format : mesh_format_of(path)) {
  case MeshFormat::ply:
    write_ply(path, mesh, threads);
    return;
  case MeshFormat::obj:
    write_obj(path, mesh, threads);
    return;
  case MeshFormat::off:
    write_off(path, mesh, threads);
    return;
  }
}

} // namespace zdg
