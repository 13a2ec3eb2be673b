// Label maps (fractions.h, io::fractions_from_labels): one material per distinct integer, named
// label_<value> or as given, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hexadapt/core/error.h"
#include "hexadapt/dist/block.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

io::MeshData labelled(std::vector<double> labels, io::ScalarType type = io::ScalarType::int32) {
  io::MeshData d = io::from_mesh(make_quad_grid(static_cast<int>(labels.size()), 1));
  io::DataArray a;
  a.name = "grain";
  a.type = type;
  a.values = std::move(labels);
  d.set_cell_array(a);
  return d;
}

io::FractionOptions labels_option() {
  io::FractionOptions o;
  o.labels = "grain";
  return o;
}

TEST(LabelFractions, OneMaterialPerLabelInIncreasingOrder) {
  const io::MeshData d = labelled({7, -2, 7, 3});
  const Fractions f = io::extract_fractions(d, labels_option(), nullptr, "in.vtu");
  EXPECT_EQ(f.names(), (std::vector<std::string>{"label_-2", "label_3", "label_7"}));
  const std::vector<int> expected{2, 0, 2, 1};
  for (CellId c : id_range<CellId>(f.n_cells())) {
    EXPECT_EQ(f.majority(c), expected[c.idx()]);
    EXPECT_TRUE(f.is_pure(c));
  }
}

// One block of a distributed grid: its materials are the labels of the whole grid
// (label_values), those it does not hold included; errors name cells by their global id.
TEST(LabelFractions, ABlockTakesTheLabelsOfTheWholeGrid) {
  const io::MeshData d = labelled({7, 3, 7});
  dist::Block block = dist::Block::whole(3, d.n_points());
  block.cell_offset = 100;
  EXPECT_THROW(io::extract_fractions(d, labels_option(), nullptr, "in.vtu", &block), OptionError);
  EXPECT_EQ(io::label_values(d, labels_option(), "in.vtu", &block),
            (std::vector<std::int64_t>{3, 7}));
  io::FractionOptions o = labels_option();
  o.label_values = {-2, 3, 7};
  const Fractions f = io::extract_fractions(d, o, nullptr, "in.vtu", &block);
  EXPECT_EQ(f.names(), (std::vector<std::string>{"label_-2", "label_3", "label_7"}));
  EXPECT_EQ(f.majority(CellId(0)), 2);
  EXPECT_EQ(f.majority(CellId(1)), 1);
  try {
    io::label_values(labelled({1, 2.5}), labels_option(), "in.vtu", &block);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 101"), std::string::npos) << e.what();
  }
}

TEST(LabelFractions, NamesGivenForSomeLabels) {
  io::FractionOptions o = labels_option();
  o.label_names = {{3, "steel"}, {99, "unused"}};
  const Fractions f = io::extract_fractions(labelled({7, 3}), o);
  EXPECT_EQ(f.names(), (std::vector<std::string>{"steel", "label_7"}));
  o.label_names = {{3, "x"}, {7, "x"}};
  EXPECT_THROW(io::extract_fractions(labelled({7, 3}), o), OptionError);
}

TEST(LabelFractions, IntegralFloatsAreLabelsToo) {
  const Fractions f =
      io::extract_fractions(labelled({1, 2, 1}, io::ScalarType::float32), labels_option());
  EXPECT_EQ(f.n_materials(), 2);
}

TEST(LabelFractions, BadLabelMapsNameTheFileArrayAndCell) {
  for (const double bad : {1.5, std::nan(""), 1e300, std::numeric_limits<double>::infinity()}) {
    SCOPED_TRACE(bad);
    try {
      io::extract_fractions(labelled({1, bad}), labels_option(), nullptr, "in.vtu");
      FAIL();
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "in.vtu");
      EXPECT_EQ(e.where(), "cell 1");
      EXPECT_NE(e.message().find("'grain'"), std::string::npos) << e.what();
      EXPECT_NE(e.message().find("not an integer"), std::string::npos) << e.what();
    }
  }
  io::FractionOptions o = labels_option();
  o.labels = "nope";
  try {
    io::extract_fractions(labelled({1}), o, nullptr, "in.vtu");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "in.vtu");
    EXPECT_NE(e.message().find("'nope'"), std::string::npos) << e.what();
  }
  o = labels_option();
  o.max_labels = 2;
  EXPECT_THROW(io::extract_fractions(labelled({1, 2, 3}), o), InputError);
  o = labels_option();
  o.arrays = {"vf_a"};
  EXPECT_THROW(io::extract_fractions(labelled({1}), o), OptionError);
  o = labels_option();
  o.void_material = "air";
  EXPECT_THROW(io::extract_fractions(labelled({1}), o), OptionError);
}

}  // namespace
}  // namespace hexadapt
