// The figures of the measure reports over values spread over ranks, each rank holding the
// values of what it owns: the same bits on every rank and for any split, equal to the
// figure of all values on one rank (the one-rank case is what the serial reports use).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "hexadapt/core/ids.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/measure/quality_report.h"

namespace hexadapt {

/// Min, mean (of the exact sum) and max of every rank's values; all 0 when there are none.
QualityStats stats(const dist::Communicator& comm, const std::vector<double>& values);

/// The sum of every rank's count.
std::int64_t total(const dist::Communicator& comm, std::int64_t count);

/// Every rank's counts added bin by bin (each rank has the same number of bins).
std::vector<index_t> summed(const dist::Communicator& comm, std::vector<index_t> counts);

/// Element k (from 0) of every rank's values in increasing order (std::nth_element's value
/// on all of them); NaN when there are not k + 1 values.
double kth_value(const dist::Communicator& comm, const std::vector<double>& values, std::int64_t k);

/// The lowest value over the ranks with the lowest global id reaching it, from each rank's
/// own (value, id); (value, -1) ranks hold nothing. `highest` picks the highest value instead.
std::pair<double, std::int64_t> extreme_with_id(const dist::Communicator& comm,
                                                std::pair<double, std::int64_t> mine, bool highest);

/// Every rank's list of ids, each increasing, merged and cut to the first k.
std::vector<CellId> first_of_ranks(const dist::Communicator& comm, std::vector<CellId> mine, int k);

}  // namespace hexadapt
