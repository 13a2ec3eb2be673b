#include "hexadapt/assign/configuration_store.h"

#include <algorithm>

#include "hexadapt/core/error.h"

namespace hexadapt::assign {

ConfigurationStore::ConfigurationStore(int keep) : keep_(keep) {
  if (keep < 1) throw OptionError("the number of stored configurations must be at least 1");
}

void ConfigurationStore::offer(double cost, const std::vector<int>& labels) {
  if (n_used_ > 0) throw InternalError("configuration offered to a store already in use");
  if (full() && !(cost < worst_cost())) return;
  // After every kept configuration of equal cost: ties stay in arrival order.
  const auto at = std::upper_bound(configs_.begin(), configs_.end(), cost,
                                   [](double v, const Configuration& c) { return v < c.cost; });
  configs_.insert(at, Configuration{cost, labels});
  if (static_cast<int>(configs_.size()) > keep_) configs_.pop_back();
  used_.assign(configs_.size(), 0);
}

const Configuration* ConfigurationStore::take(int i) {
  used_[static_cast<std::size_t>(i)] = 1;
  ++n_used_;
  return &configs_[static_cast<std::size_t>(i)];
}

const Configuration* ConfigurationStore::take_next() {
  for (int i = 0; i < size(); ++i)
    if (!used_[static_cast<std::size_t>(i)]) return take(i);
  return nullptr;
}

}  // namespace hexadapt::assign
