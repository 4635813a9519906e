#include <zdg/arith/error.hpp>
#include <zdg/convergence/check/record.hpp>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace zdg::check {

Record& Record::integer(std::string name, BigInt v, Shrink s) {
  Field f;
  f.name = std::move(name);
  f.kind = FieldKind::integer;
  f.ints = {std::move(v)};
  f.shrink = s;
  fields.push_back(std::move(f));
  return *this;
}

Record& Record::boolean(std::string name, bool v) {
  Field f;
  f.name = std::move(name);
  f.kind = FieldKind::boolean;
  f.flag = v;
  fields.push_back(std::move(f));
  return *this;
}

Record& Record::text(std::string name, std::string v) {
  Field f;
  f.name = std::move(name);
  f.kind = FieldKind::text;
  f.texts = {std::move(v)};
  fields.push_back(std::move(f));
  return *this;
}

Record& Record::texts(std::string name, std::vector<std::string> v) {
  Field f;
  f.name = std::move(name);
  f.kind = FieldKind::texts;
  f.texts = std::move(v);
  fields.push_back(std::move(f));
  return *this;
}

Record& Record::array(std::string name, std::vector<std::size_t> shape, std::vector<BigInt> values,
                      Shrink s, bool numbers) {
  if (shape_size(shape) != values.size()) {
    throw InvalidArgument("record: array '" + name + "' has " + std::to_string(values.size()) +
                          " values for its shape");
  }
  Field f;
  f.name = std::move(name);
  f.kind = FieldKind::array;
  f.shape = std::move(shape);
  f.ints = std::move(values);
  f.shrink = s;
  f.numbers = numbers;
  fields.push_back(std::move(f));
  return *this;
}

bool Record::has(const std::string& name) const {
  return std::any_of(fields.begin(), fields.end(), [&](const Field& f) { return f.name == name; });
}

const Field& Record::at(const std::string& name) const {
  for (const auto& f : fields) {
    if (f.name == name) return f;
  }
  throw InvalidArgument("record: no field '" + name + "'");
}

Field& Record::at(const std::string& name) {
  for (auto& f : fields) {
    if (f.name == name) return f;
  }
  throw InvalidArgument("record: no field '" + name + "'");
}

const BigInt& Record::int_of(const std::string& name) const {
  const Field& f = at(name);
  if (f.kind != FieldKind::integer) throw InvalidArgument("record: '" + name + "' is no integer");
  return f.ints[0];
}

std::int64_t Record::i64_of(const std::string& name) const {
  return int_cast<Int64>(int_of(name)).value();
}

bool operator==(const Field& a, const Field& b) {
  // The shrink mode and the layout flags say how a value is handled, not what it is.
  return a.name == b.name && a.kind == b.kind && a.ints == b.ints && a.shape == b.shape &&
         a.texts == b.texts && a.flag == b.flag;
}

std::size_t shape_size(const std::vector<std::size_t>& shape) {
  std::size_t n = 1;
  for (auto e : shape) n *= e;
  return n;
}

namespace {

void append_string(std::string& out, const std::string& s) {
  out += '"';
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  out += '"';
}

void append_array(std::string& out, const Field& f, std::size_t axis, std::size_t& pos) {
  if (axis == 0 && f.shape.size() == 2 && !f.columns.empty() && f.columns.size() == f.shape[1]) {
    out += '[';
    for (std::size_t k = 0; k < f.shape[0]; ++k) {
      if (k > 0) out += ',';
      out += '{';
      for (std::size_t c = 0; c < f.shape[1]; ++c) {
        if (c > 0) out += ',';
        append_string(out, f.columns[c]);
        out += ':';
        const std::string v = f.ints[pos++].str();
        if (f.numbers) {
          out += v;
        } else {
          append_string(out, v);
        }
      }
      out += '}';
    }
    out += ']';
    return;
  }
  out += '[';
  for (std::size_t k = 0; k < f.shape[axis]; ++k) {
    if (k > 0) out += ',';
    if (axis + 1 == f.shape.size()) {
      const std::string v = f.ints[pos++].str();
      if (f.numbers) {
        out += v;
      } else {
        append_string(out, v);
      }
    } else {
      append_array(out, f, axis + 1, pos);
    }
  }
  out += ']';
}

void append_value(std::string& out, const Field& f) {
  switch (f.kind) {
  case FieldKind::integer:
    append_string(out, f.ints[0].str());
    break;
  case FieldKind::boolean:
    out += f.flag ? "true" : "false";
    break;
  case FieldKind::text:
    append_string(out, f.texts[0]);
    break;
  case FieldKind::texts:
    out += '[';
    for (std::size_t k = 0; k < f.texts.size(); ++k) {
      if (k > 0) out += ',';
      append_string(out, f.texts[k]);
    }
    out += ']';
    break;
  case FieldKind::array: {
    std::size_t pos = 0;
    if (f.shape.empty()) {
      out += "[]";
    } else {
      append_array(out, f, 0, pos);
    }
    break;
  }
  }
}

// The array without the slice `index` of `axis`.
Field drop_slice(const Field& f, std::size_t axis, std::size_t index) {
  Field g = f;
  g.ints.clear();
  std::size_t inner = 1;
  for (std::size_t k = axis + 1; k < f.shape.size(); ++k) inner *= f.shape[k];
  const std::size_t ext = f.shape[axis];
  for (std::size_t i = 0; i < f.ints.size(); ++i) {
    if ((i / inner) % ext != index) g.ints.push_back(f.ints[i]);
  }
  g.shape[axis] = ext - 1;
  return g;
}

// Rows [lo, hi) of axis 0.
Field keep_rows(const Field& f, std::size_t lo, std::size_t hi) {
  Field g = f;
  const std::size_t inner = f.shape[0] == 0 ? 0 : f.ints.size() / f.shape[0];
  g.ints.assign(f.ints.begin() + static_cast<std::ptrdiff_t>(lo * inner),
                f.ints.begin() + static_cast<std::ptrdiff_t>(hi * inner));
  g.shape[0] = hi - lo;
  return g;
}

} // namespace

std::string to_json(const Field& f) {
  std::string out;
  append_value(out, f);
  return out;
}

std::string to_json(const Record& r) {
  std::string out = "{";
  for (std::size_t k = 0; k < r.fields.size(); ++k) {
    if (k > 0) out += ',';
    append_string(out, r.fields[k].name);
    out += ':';
    append_value(out, r.fields[k]);
  }
  out += '}';
  return out;
}

std::vector<BigInt> integer_shrinks(const BigInt& v) {
  std::vector<BigInt> out;
  if (v == 0) return out;
  out.push_back(BigInt(0));
  if (v < 0) out.push_back(BigInt(-v));
  const BigInt one = v > 0 ? BigInt(1) : BigInt(-1);
  if (v != one) out.push_back(one);
  if (v / 2 != 0 && v / 2 != one) out.push_back(BigInt(v / 2));
  BigInt d = v / 2; // towards 0
  while (d != 0) {
    out.push_back(v - d);
    d /= 2;
  }
  if (out.back() != v - one) out.push_back(v - one);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Record> shrink_candidates(const Record& r) {
  std::vector<Record> out;
  auto with = [&](std::size_t k, Field f) {
    Record c = r;
    c.fields[k] = std::move(f);
    out.push_back(std::move(c));
  };
  // Structure first (fewer points, smaller images), then values.
  for (std::size_t k = 0; k < r.fields.size(); ++k) {
    const Field& f = r.fields[k];
    if (f.kind != FieldKind::array || f.shape.empty()) continue;
    const std::size_t n = f.shape[0];
    if (f.shrink == Shrink::path && n > 1) {
      std::vector<std::pair<std::size_t, std::size_t>> keeps = {
          {0, 1}, {0, n / 2}, {n - n / 2, n}, {0, n - 1}, {1, n}};
      for (auto [lo, hi] : keeps) {
        if (hi > lo && hi - lo < n) with(k, keep_rows(f, lo, hi));
      }
    } else if (f.shrink == Shrink::list && n > 0) {
      if (n > 1) {
        with(k, keep_rows(f, 0, n / 2));
        with(k, keep_rows(f, n / 2, n));
      }
      for (std::size_t i = 0; i < std::min<std::size_t>(n, 64); ++i) with(k, drop_slice(f, 0, i));
    } else if (f.shrink == Shrink::image) {
      for (std::size_t axis = 0; axis < f.shape.size(); ++axis) {
        if (f.shape[axis] <= 1) continue;
        with(k, drop_slice(f, axis, f.shape[axis] - 1));
        with(k, drop_slice(f, axis, 0));
      }
    }
  }
  for (std::size_t k = 0; k < r.fields.size(); ++k) {
    const Field& f = r.fields[k];
    if (f.shrink == Shrink::none) continue;
    if (f.kind == FieldKind::integer) {
      for (auto& s : integer_shrinks(f.ints[0])) {
        Field g = f;
        g.ints[0] = s;
        with(k, std::move(g));
      }
    } else if (f.kind == FieldKind::array && f.shrink == Shrink::path && f.shape.size() == 2 &&
               f.shape[0] > 0) {
      // Translate the whole path: its first point towards the origin, one axis at a time.
      const std::size_t d = f.shape[1];
      for (std::size_t axis = 0; axis < d; ++axis) {
        for (auto& s : integer_shrinks(f.ints[axis])) {
          Field g = f;
          const BigInt shift = s - f.ints[axis];
          for (std::size_t i = 0; i < f.shape[0]; ++i) g.ints[i * d + axis] += shift;
          with(k, std::move(g));
        }
      }
    } else if (f.kind == FieldKind::array && f.shrink == Shrink::image) {
      for (std::size_t i = 0; i < f.ints.size(); ++i) {
        if (f.ints[i] == 0) continue;
        Field g = f;
        g.ints[i] = 0;
        with(k, std::move(g));
      }
    } else if (f.kind == FieldKind::array &&
               (f.shrink == Shrink::list || f.shrink == Shrink::toward_zero)) {
      for (std::size_t i = 0; i < f.ints.size(); ++i) {
        for (auto& s : integer_shrinks(f.ints[i])) {
          Field g = f;
          g.ints[i] = s;
          with(k, std::move(g));
        }
      }
    }
  }
  return out;
}

} // namespace zdg::check
