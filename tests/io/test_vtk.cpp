// io/vtk: the appended raw layout byte by byte (UInt64 count, little-endian values in the declared
// type, offsets into the block), cell indices Int32 until 2^31 - 1, and the arrays refused.
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "agglo/io/vtk.hpp"

using namespace agglo::io;

namespace {
// The bytes after the '_' that opens the appended data, without the closing tags.
std::string appended(const std::string& file) {
  const auto start = file.find('_', file.find("<AppendedData encoding=\"raw\">")) + 1;
  const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
  EXPECT_EQ(file.substr(file.size() - tail.size()), tail);
  return file.substr(start, file.size() - tail.size() - start);
}
template <class T>
T at(const std::string& bytes, std::size_t offset) {
  T v;
  std::memcpy(&v, bytes.data() + offset, sizeof(T));  // the test machine is little-endian (x86_64)
  return v;
}
}  // namespace

TEST(Vtk, AppendedLayout) {
  std::ostringstream o;
  write_vtk(o, "UnstructuredGrid", "NumberOfPoints=\"2\" NumberOfCells=\"0\"",
            {{"PointData", "Scalars=\"a\"",
              {{"a", "Int32", 1, {-2, 7}}, {"b", "Float64", 1, {-0.5, 1e-310}}, {"c", "UInt8", 1, {255, 1}}}}});
  const std::string f = o.str();
  EXPECT_NE(f.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(f.find("Name=\"a\" NumberOfComponents=\"1\" format=\"appended\" offset=\"0\""), std::string::npos);
  EXPECT_NE(f.find("Name=\"b\" NumberOfComponents=\"1\" format=\"appended\" offset=\"16\""), std::string::npos);
  EXPECT_NE(f.find("Name=\"c\" NumberOfComponents=\"1\" format=\"appended\" offset=\"40\""), std::string::npos);
  const std::string b = appended(f);
  ASSERT_EQ(b.size(), 16u + 24u + 10u);
  EXPECT_EQ(at<std::uint64_t>(b, 0), 8u);
  EXPECT_EQ(at<std::int32_t>(b, 8), -2);
  EXPECT_EQ(at<std::int32_t>(b, 12), 7);
  EXPECT_EQ(at<std::uint64_t>(b, 16), 16u);
  EXPECT_EQ(at<double>(b, 24), -0.5);
  EXPECT_EQ(at<double>(b, 32), 1e-310);  // subnormal, exact
  EXPECT_EQ(at<std::uint64_t>(b, 40), 2u);
  EXPECT_EQ(static_cast<unsigned char>(b[48]), 255);
  EXPECT_EQ(static_cast<unsigned char>(b[49]), 1);
}

TEST(Vtk, PolyDataVertices) {
  std::ostringstream o;
  write_vtp(o, {{1, 2, 3}, {4, 5, 6}}, {{"radius", "Float64", 1, {0.25, 0.5}}});
  const std::string f = o.str();
  EXPECT_NE(f.find("<PointData Scalars=\"radius\">"), std::string::npos);
  EXPECT_NE(f.find("type=\"Int32\" Name=\"connectivity\""), std::string::npos);
  const std::string b = appended(f);
  // radius (8 + 16), Points (8 + 48), connectivity (8 + 8), offsets (8 + 8)
  ASSERT_EQ(b.size(), 24u + 56u + 16u + 16u);
  EXPECT_EQ(at<double>(b, 24 + 8 + 5 * 8), 6.0);
  EXPECT_EQ(at<std::int32_t>(b, 80 + 8 + 4), 1);   // connectivity of vertex 1
  EXPECT_EQ(at<std::int32_t>(b, 96 + 8 + 4), 2);   // offset of vertex 1
}

TEST(Vtk, IndexType) {
  EXPECT_EQ(vtk_index_type(2147483647u), "Int32");
  EXPECT_EQ(vtk_index_type(2147483648u), "Int64");
}

TEST(Vtk, RefusedArrays) {
  std::ostringstream o;
  EXPECT_THROW(write_vtk(o, "PolyData", "", {{"PointData", "", {{"x", "Float32", 1, {1}}}}}), std::invalid_argument);
  EXPECT_THROW(write_vtk(o, "PolyData", "", {{"PointData", "", {{"x", "Float64", 3, {1, 2}}}}}), std::invalid_argument);
}
