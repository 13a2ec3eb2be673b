#include "exodus_guard.h"

#include <netcdf.h>

#include <vector>

#include "exodus_file.h"
#include "hexadapt/core/error.h"

namespace hexadapt::io::detail {

namespace {

// The lengths of the dimensions of variable `name`, or nothing when there is no such variable.
bool variable_shape(const ExodusFile& f, const std::string& name, std::vector<std::size_t>& shape) {
  int varid = -1, rank = 0;
  if (nc_inq_varid(f.id(), name.c_str(), &varid) != NC_NOERR) return false;
  if (nc_inq_varndims(f.id(), varid, &rank) != NC_NOERR || rank < 0 || rank > NC_MAX_VAR_DIMS)
    throw InputError(f.path(), "variable " + name, "unreadable dimensions");
  std::vector<int> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && nc_inq_vardimid(f.id(), varid, dims.data()) != NC_NOERR)
    throw InputError(f.path(), "variable " + name, "unreadable dimensions");
  shape.clear();
  for (int d : dims) {
    std::size_t n = 0;
    if (nc_inq_dimlen(f.id(), d, &n) != NC_NOERR)
      throw InputError(f.path(), "variable " + name, "unreadable dimension length");
    shape.push_back(n);
  }
  return true;
}

}  // namespace

void check_variable_size(const ExodusFile& f, const std::string& name, std::size_t values,
                         bool required) {
  std::vector<std::size_t> shape;
  if (!variable_shape(f, name, shape)) {
    if (required) throw InputError(f.path(), "variable " + name, "missing");
    return;
  }
  std::size_t n = 1;
  for (std::size_t len : shape) {
    if (len != 0 && n > values / len + 1) {
      n = values + 1;
      break;
    }
    n *= len;
  }
  if (n != values)
    throw InputError(f.path(), "variable " + name,
                     "holds " + std::to_string(n) + " values where the header's counts need " +
                         std::to_string(values));
}

void read_int_variable(const ExodusFile& f, const std::string& name, std::vector<int>& values) {
  check_variable_size(f, name, values.size());
  int varid = -1;
  if (nc_inq_varid(f.id(), name.c_str(), &varid) != NC_NOERR ||
      nc_get_var_int(f.id(), varid, values.data()) != NC_NOERR)
    throw InputError(f.path(), "variable " + name, "unreadable");
}

void check_string_length(const ExodusFile& f, const std::string& name, std::size_t max_length) {
  std::vector<std::size_t> shape;
  if (!variable_shape(f, name, shape)) return;
  for (std::size_t k = 1; k < shape.size(); ++k)
    if (shape[k] > max_length)
      throw InputError(f.path(), "variable " + name,
                       "strings of " + std::to_string(shape[k]) + " characters, more than " +
                           std::to_string(max_length));
}

void check_attribute_length(const ExodusFile& f, const std::string& name,
                            const std::string& attribute, std::size_t max_length) {
  int varid = -1;
  if (nc_inq_varid(f.id(), name.c_str(), &varid) != NC_NOERR) return;
  std::size_t n = 0;
  if (nc_inq_attlen(f.id(), varid, attribute.c_str(), &n) != NC_NOERR) return;
  if (n > max_length)
    throw InputError(f.path(), "variable " + name,
                     "attribute " + attribute + " of " + std::to_string(n) +
                         " characters, more than " + std::to_string(max_length));
}

}  // namespace hexadapt::io::detail
