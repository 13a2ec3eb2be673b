// Sizes in bytes as people read them in messages.
#pragma once

#include <string>

namespace hexadapt {

/// A size for people, in powers of 1000: "512 kB", "43 MB", "25.3 GB".
std::string size_text(double bytes);

}  // namespace hexadapt
