#include "hexadapt/core/parallel.h"

#include <omp.h>

#include "hexadapt/core/error.h"

namespace hexadapt {

void set_threads(int n) {
  if (n < 0) throw OptionError("thread count must be >= 0");
  omp_set_num_threads(n == 0 ? omp_get_num_procs() : n);
}

int n_threads() { return omp_get_max_threads(); }

}  // namespace hexadapt
