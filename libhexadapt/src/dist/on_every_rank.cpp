#include "hexadapt/dist/on_every_rank.h"

#include <new>
#include <string>
#include <vector>

namespace hexadapt::dist {

namespace {

// An exception's type, as it travels between ranks.
enum class Kind : int { none, input, mesh, io, option, resource, internal, bad_alloc, other };

std::string text(Buffer& b) {
  const std::vector<char> c = b.get_vector<char>();
  return std::string(c.begin(), c.end());
}

void put_text(Buffer& b, const std::string& s) {
  b.put_vector(std::vector<char>(s.begin(), s.end()));
}

// The exception `error` as bytes: its kind, then its message (an InputError's three parts).
Buffer packed(const std::exception_ptr& error) {
  Buffer b;
  const auto put = [&](Kind k, const std::string& what) {
    b.put(static_cast<int>(k));
    put_text(b, what);
  };
  try {
    std::rethrow_exception(error);
  } catch (const InputError& e) {
    b.put(static_cast<int>(Kind::input));
    put_text(b, e.file());
    put_text(b, e.where());
    put_text(b, e.message());
  } catch (const MeshError& e) {
    put(Kind::mesh, e.what());
  } catch (const IoError& e) {
    put(Kind::io, e.what());
  } catch (const OptionError& e) {
    put(Kind::option, e.what());
  } catch (const ResourceError& e) {
    put(Kind::resource, e.what());
  } catch (const InternalError& e) {
    put(Kind::internal, e.what());
  } catch (const std::bad_alloc&) {
    put(Kind::bad_alloc, "");
  } catch (const std::exception& e) {
    put(Kind::other, e.what());
  } catch (...) {
    put(Kind::other, "an exception of unknown type");
  }
  return b;
}

// The exception `b` holds (packed), or none.
std::exception_ptr unpacked(Buffer& b) {
  const auto kind = static_cast<Kind>(b.get<int>());
  if (kind == Kind::none) return nullptr;
  if (kind == Kind::input) {
    std::string file = text(b), where = text(b);
    return std::make_exception_ptr(InputError(std::move(file), std::move(where), text(b)));
  }
  const std::string what = text(b);
  switch (kind) {
    case Kind::mesh: return std::make_exception_ptr(MeshError(what));
    case Kind::io: return std::make_exception_ptr(IoError(what));
    case Kind::option: return std::make_exception_ptr(OptionError(what));
    case Kind::resource: return std::make_exception_ptr(ResourceError(what));
    case Kind::bad_alloc: return std::make_exception_ptr(std::bad_alloc());
    default: return std::make_exception_ptr(InternalError(what));
  }
}

}  // namespace

CommonError::CommonError(int rank, std::exception_ptr original)
    : Error("rank " + std::to_string(rank) + " stopped"), rank_(rank), original_(std::move(original)) {}

void on_every_rank(const Communicator& comm, const std::function<void()>& f) {
  if (comm.size() == 1) return f();
  Buffer mine;
  try {
    f();
    mine.put(static_cast<int>(Kind::none));
  } catch (const CommonError&) {
    throw;  // every rank threw it together
  } catch (...) {
    mine = packed(std::current_exception());
  }
  std::vector<Buffer> all = all_gather(comm, mine);
  for (std::size_t r = 0; r < all.size(); ++r)
    if (std::exception_ptr e = unpacked(all[r])) throw CommonError(static_cast<int>(r), e);
}

}  // namespace hexadapt::dist
