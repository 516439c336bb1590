#include "fair/faired_run.hpp"

namespace gf {

LacPoint FairedChain::start_frame() const {
  if (!spirals.empty()) return spirals.front().start();
  if (!segments.empty()) return segments.front().start();
  return closed ? guide->guide->frame_at(guide->s0) : guide->start;
}

LacPoint FairedChain::end_frame() const {
  if (!spirals.empty()) return spirals.back().end();
  if (!segments.empty()) return segments.back().end();
  return closed ? guide->guide->frame_at(guide->s1) : guide->end;
}

}  // namespace gf
