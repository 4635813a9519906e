// Point files and digital path files parsed from text: the points and their lines against the
// text they were printed to (round trip), and every class of malformed text an IoError naming
// the line.
#include <zdg/kernel/io/point_file.hpp>

#include "tests/support/tower.hpp"

#include <string>
#include <vector>

namespace {

using namespace zdg;

// Theorem (round trip): printing points one a line, in any decimal spelling (signs, leading
// zeros, spaces or tabs, comments, blank lines, CRLF), and parsing the text gives the points
// back, each with the line it was printed on.
TEST(PointFile, RoundTripWithCommentsBlanksAndLeadingZeros) {
  zdg::test::check_property([] {
    const int dim = *rc::gen::element(2, 3);
    const int n = *rc::gen::inRange(1, 30);
    std::string text;
    std::vector<BigInt> coords;
    std::vector<std::size_t> lines;
    std::size_t line = 0;
    for (int k = 0; k < n; ++k) {
      if (*rc::gen::inRange(0, 4) == 0) {
        text += *rc::gen::element<std::string>("\n", "# comment 1 2 3\n", "   \t\n", "\r\n");
        ++line;
      }
      for (int c = 0; c < dim; ++c) {
        BigInt v = BigInt(*zdg::test::edgy_int64()) *
                   (*rc::gen::inRange(0, 3) == 0 ? BigInt(1) << 70 : BigInt(1));
        coords.push_back(v);
        std::string digits = (v < 0 ? BigInt(-v) : v).str();
        text += *rc::gen::element<std::string>(" ", "\t", "  ");
        text += (v < 0 ? "-" : *rc::gen::element<std::string>("", "+")) +
                std::string(static_cast<std::size_t>(*rc::gen::inRange(0, 3)), '0') + digits;
      }
      text += *rc::gen::element<std::string>("\n", "\r\n", " # trailing comment\n");
      lines.push_back(++line);
    }
    const auto p = parse_point_file(text, "t", {2, 3});
    RC_ASSERT(p.dim == dim);
    RC_ASSERT(p.coords == coords);
    RC_ASSERT(p.lines == lines);
  });
}

TEST(PointFile, MalformedTextNamesTheLine) {
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"", "t: no point (empty file)"},
      {"# only a comment\n\n", "no point"},
      {"1 2 3 4\n", "t:1: expected 2 or 3 integers a line, got 4 fields"},
      {"1 2\n3 4 5\n", "t:2: 3 fields in a file of 2D points"},
      {"1 2\n3 x\n", "t:2: 'x' is not an integer"},
      {"1 2\n3 0x10\n", "t:2: '0x10' is not an integer"},
      {"1 2\n3 1e3\n", "t:2: '1e3' is not an integer"},
      {"1 2\n3 4/2\n", "t:2:"},
      {std::string("1 2\n3 \0\n", 8), "t:2: '?' is not an integer"},
  };
  for (const auto& c : cases) {
    try {
      parse_point_file(c.text, "t", {2, 3});
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    }
  }
  // Leading zeros are decimal (issue #18: they were octal through the BigInt parser).
  auto p = parse_point_file("010 -08\n", "t", {2});
  EXPECT_EQ(p.coords, (std::vector<BigInt>{BigInt(10), BigInt(-8)}));
}

TEST(DigitalPathFile, PointsOrAFreemanChain) {
  auto pts = parse_digital_path_file("# a path\n0 0\n1 0\n\n1 1\n", "t");
  EXPECT_FALSE(pts.chain);
  EXPECT_EQ(pts.points,
            (std::vector<Point2<BigInt>>{
                {BigInt(0), BigInt(0)}, {BigInt(1), BigInt(0)}, {BigInt(1), BigInt(1)}}));
  EXPECT_EQ(pts.lines, (std::vector<std::size_t>{2, 3, 5}));
  auto ch = parse_digital_path_file("\n010 -2 0 1 2 3\n", "t");
  ASSERT_TRUE(ch.chain);
  EXPECT_EQ(ch.chain->start, (Point2<std::int64_t>{10, -2}));
  EXPECT_EQ(ch.chain->codes, "0123");
  EXPECT_EQ(ch.chain_line, 2u);
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"0 0 0140\n", "t:1: Freeman chain: invalid code '4'"},
      {"0 0 0101\n1 1\n", "t:2: unexpected text after the Freeman chain"},
      {"0 0\n1\n", "t:2: expected a point 'x y'"},
      {"0 0\n1 y\n", "t:2: expected two integers"},
      {"99999999999999999999 0 01\n", "t:1: Freeman chain: x0"},
      {"", "no point"},
  };
  for (const auto& c : cases) {
    try {
      parse_digital_path_file(c.text, "t");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    }
  }
}

} // namespace
