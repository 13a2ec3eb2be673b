// A named case of hexadapt-generate run through the library as the stage tools chain it:
// generate -> fractions -> assign, handed to a callback with the grid (QuadMesh or HexMesh).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "hexadapt/assign/assign.h"
#include "hexadapt/generate/generate.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/fractions_reader.h"

namespace hexadapt::test {

struct GeneratedCase {
  std::string name;
  std::vector<int> dims;
  double time = -1;  // < 0: the case's default
  int extrude = 0;
  double jitter = 0;
};

/// A name usable as a test name: case, dims, time in hundredths, extrusion, jitter.
inline std::string label(const GeneratedCase& c) {
  std::string s = c.name;
  for (int d : c.dims) s += "_" + std::to_string(d);
  if (c.time >= 0) s += "_t" + std::to_string(static_cast<int>(c.time * 100));
  if (c.extrude) s += "_x" + std::to_string(c.extrude);
  if (c.jitter > 0) s += "_jitter";
  for (char& ch : s)
    if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s;
}

/// Calls fn(grid, fractions, assigned materials) on the generated case.
template <class F>
void with_generated_case(const GeneratedCase& c, F&& fn) {
  generate::GenerateOptions o;
  o.case_name = c.name;
  o.dims = c.dims;
  if (c.time >= 0) o.time = c.time;
  o.extrude = c.extrude;
  o.jitter = c.jitter;
  const auto g = generate::generate(o);
  const Fractions f = io::extract_fractions(g.data, io::FractionOptions{});
  std::visit(
      [&](const auto& grid) {
        const auto a = assign::assign_materials(grid, f);
        fn(grid, f, a.correction.labels);
      },
      io::to_mesh(g.data));
}

}  // namespace hexadapt::test
