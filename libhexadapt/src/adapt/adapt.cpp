#include "hexadapt/adapt/adapt.h"

#include <string>

#include "base_pipeline.h"
#include "hexadapt/core/error.h"

namespace hexadapt {

AdaptMethod parse_adapt_method(const std::string& name) {
  if (name == "base") return AdaptMethod::base;
  if (name == "guaranteed") return AdaptMethod::guaranteed;
  throw OptionError("unknown adaptation method '" + name + "' (expected base or guaranteed)");
}

std::string to_string(AdaptMethod method) {
  return method == AdaptMethod::base ? "base" : "guaranteed";
}

namespace {

void check_options(const AdaptOptions& o) {
  if (!(o.threshold > -1 && o.threshold <= 1))
    throw OptionError("threshold must be in (-1, 1], got " + std::to_string(o.threshold));
  if (o.steps < 1) throw OptionError("steps must be at least 1, got " + std::to_string(o.steps));
  if (o.method == AdaptMethod::guaranteed)
    throw OptionError("the guaranteed method is not implemented yet; use --method base");
}

}  // namespace

template <class M>
AdaptResult<M> adapt(const M& grid, const Fractions& fractions,
                     const IdVector<CellId, int>& material, const AdaptOptions& options) {
  check_options(options);
  switch (options.method) {
    case AdaptMethod::base:
      return detail::run_base_pipeline(grid, fractions, material, options);
    case AdaptMethod::guaranteed:
      break;
  }
  throw InternalError("unhandled adaptation method");
}

template AdaptResult<QuadMesh> adapt<QuadMesh>(const QuadMesh&, const Fractions&,
                                               const IdVector<CellId, int>&, const AdaptOptions&);
template AdaptResult<HexMesh> adapt<HexMesh>(const HexMesh&, const Fractions&,
                                             const IdVector<CellId, int>&, const AdaptOptions&);

}  // namespace hexadapt
