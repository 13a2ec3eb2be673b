// ConfigurationStore: the K best manifold configurations of one node, and which of them
// have been used (paper sec. 3.2, "validConfigs" of Algorithm 1 and "store" of Algorithm 2).
//
// Configurations are kept in increasing cost; equal costs keep their arrival order, which
// is the enumeration's deterministic order. A node treated again takes the next unused
// configuration: every visit consumes one, so the correction cannot cycle forever (the
// paper's livelock avoidance), and running out is the failure the user fixes with a larger K.
// A visit may skip ahead to a dearer unused configuration (take_preferring); skipped ones
// stay available to later visits.
#pragma once

#include <vector>

namespace hexadapt::assign {

struct Configuration {
  double cost = 0;          ///< eq. (4) over the ball
  std::vector<int> labels;  ///< one material per ball cell, in ball order
};

class ConfigurationStore {
 public:
  explicit ConfigurationStore(int keep = 20);

  /// Keeps the configuration if it is among the `keep` best seen so far.
  void offer(double cost, const std::vector<int>& labels);
  bool full() const { return static_cast<int>(configs_.size()) >= keep_; }
  /// Cost of the last kept configuration (meaningful once full()).
  double worst_cost() const { return configs_.back().cost; }

  int size() const { return static_cast<int>(configs_.size()); }
  const Configuration& operator[](int i) const { return configs_[static_cast<std::size_t>(i)]; }

  /// The best configuration not used yet, nullptr when all were used.
  const Configuration* take_next();
  /// The best unused configuration satisfying `good`, else the best unused one; nullptr
  /// when all were used. Either way it is marked used.
  template <class Good>
  const Configuration* take_preferring(Good good) {
    for (int i = 0; i < size(); ++i)
      if (!used_[static_cast<std::size_t>(i)] && good(configs_[static_cast<std::size_t>(i)]))
        return take(i);
    return take_next();
  }
  int used() const { return n_used_; }

 private:
  const Configuration* take(int i);

  int keep_;
  int n_used_ = 0;
  std::vector<Configuration> configs_;
  std::vector<char> used_;
};

}  // namespace hexadapt::assign
