// Fractions: the volume fraction of every material in every cell (dense cells x materials),
// as the stages use them: valid, each cell summing to 1. Reading them from a file's arrays,
// with their validation and repair, is io/fractions_reader.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hexadapt/core/ids.h"

namespace hexadapt {

/// Each cell's one material: an index into Fractions::names(). The type every stage passes a
/// grid's assignment in.
using CellMaterials = IdVector<CellId, int>;

class Fractions {
 public:
  Fractions() = default;
  Fractions(index_t n_cells, std::vector<std::string> names);

  index_t n_cells() const { return n_cells_; }
  int n_materials() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  /// Index of the material with this name, -1 if none.
  int find(const std::string& name) const;

  double operator()(CellId c, int m) const { return data_[slot(c, m)]; }
  double& operator()(CellId c, int m) { return data_[slot(c, m)]; }
  /// The material with the largest fraction in c, ties to the lowest index.
  int majority(CellId c) const;
  /// True when one material holds the whole cell.
  bool is_pure(CellId c) const;

 private:
  std::size_t slot(CellId c, int m) const {
    return c.idx() * names_.size() + static_cast<std::size_t>(m);
  }
  index_t n_cells_ = 0;
  std::vector<std::string> names_;
  std::vector<double> data_;
};

/// Each cell's majority material (Fractions::majority): the paper's initial assignment, eq. (2).
CellMaterials majority_materials(const Fractions& fractions);

}  // namespace hexadapt
