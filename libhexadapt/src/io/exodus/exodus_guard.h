// Private to the Exodus II reader: checks, through the netCDF API, that the variables the
// Exodus library reads whole have the sizes the reader allocates for them. The library
// trusts the file: a variable whose dimensions do not match the counts of the header (an
// element map on the nodes' dimension, an element type string longer than its buffer) makes
// it write past the caller's arrays.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace hexadapt::io::detail {

class ExodusFile;

/// Throws InputError unless netCDF variable `name` is missing (and `required` is false) or
/// holds exactly `values` values.
void check_variable_size(const ExodusFile& f, const std::string& name, std::size_t values,
                         bool required = true);

/// Reads integer variable `name` into `values`, which must be its size (check_variable_size)
/// straight from netCDF: by its name, not through the Exodus library's lookup of a block's
/// id (the fuzzer once saw the heap past a connectivity buffer read that way overwritten;
/// a cache of ids outliving a file is the suspected cause, not confirmed). Throws InputError.
void read_int_variable(const ExodusFile& f, const std::string& name, std::vector<int>& values);

/// Throws InputError unless every dimension of variable `name` after the first is at most
/// `max_length` (name tables: the Exodus library copies each row into a fixed buffer).
void check_string_length(const ExodusFile& f, const std::string& name, std::size_t max_length);

/// Throws InputError unless text attribute `attribute` of variable `name`, if there is one,
/// holds at most `max_length` characters.
void check_attribute_length(const ExodusFile& f, const std::string& name,
                            const std::string& attribute, std::size_t max_length);

}  // namespace hexadapt::io::detail
