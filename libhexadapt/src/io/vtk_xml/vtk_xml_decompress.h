// Private to the VTK XML reader: the block compressors VTK's XML writers offer
// (vtkZLibDataCompressor, vtkLZ4DataCompressor, vtkLZMADataCompressor). All three share
// VTK's block table (see vtk_xml_payload.h); each block is one independent unit of its
// format: a zlib stream, an LZ4 block (LZ4_compress_default's format) or an .xz stream.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace hexadapt::io::detail {

enum class Compressor { none, zlib, lz4, lzma };

/// The compressor named by the VTKFile attribute `compressor` ("" is none); nullopt for a
/// name VTK does not write.
std::optional<Compressor> compressor_of(const std::string& name);

/// "zlib", "LZ4", "LZMA" for messages.
const char* compressor_name(Compressor c);

/// Largest output per input byte a block of this format can reach (plus a small constant
/// for headers): a block claiming more is a lie, refused before anything is allocated.
std::uint64_t max_expansion(Compressor c);

/// Decompresses one block of `n` bytes into exactly `size` bytes at dst; false when the data
/// is corrupt or does not decompress to that size. Never writes past dst + size.
bool decompress_block(Compressor c, const unsigned char* src, std::uint64_t n, unsigned char* dst,
                      std::uint64_t size);

}  // namespace hexadapt::io::detail
