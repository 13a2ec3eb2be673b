// The guaranteed method's decisions taken by every rank together (RankDecisions) when the ranks
// adapt their parts of a grid (adapt_on_ranks.h).
#pragma once

#include "held_part.h"

namespace hexadapt {

/// A cell that the mending run of any rank holding it left failing is left out by all of them
/// (each rank sends its failing ghosts to their owners, which send back every holder's verdicts
/// on their own cells); the shares of the automatic choice are summed. Every rank calls it; the
/// decisions hold `comm`, `s` and `block` by reference.
RankDecisions rank_decisions(const dist::Communicator& comm, const HeldPart& s,
                             const dist::Block& block);

}  // namespace hexadapt
