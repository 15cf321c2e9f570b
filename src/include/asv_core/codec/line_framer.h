// One line of an NMEA input (a UDP datagram, a TCP or serial line, a file line) into sentences, every
// rejection counted by reason: what ais_node, arpa_node and own_ship_node feed their decoders with.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "asv_core/codec/nmea.h"

namespace asv::nmea {

// Splits a line into sentences, resynchronising after garbage or a broken sentence at the next `$`/`!`
// (a receiver that glues sentences or drops bytes must not cost the valid ones after it).
class LineFramer {
public:
  explicit LineFramer(const FramerConfig& config = {}) : config_(config) {}
  // Calls `on_sentence` for each valid sentence of `line`.
  void frame(std::string_view line, const std::function<void(const Sentence&)>& on_sentence);

  std::uint64_t sentences() const { return sentences_; }
  // Lines, or text before a sentence start, that hold no sentence at all.
  std::uint64_t garbage() const { return garbage_; }
  std::uint64_t rejected(Reject r) const { return rejects_[static_cast<std::size_t>(r)]; }
  std::uint64_t checksumFailures() const;  // missing, malformed or wrong sentence/tag-block checksums
  std::uint64_t totalRejected() const;     // garbage and every rejected sentence
  // The counters for a diagnostics page, in this order: sentences framed, checksum failures, garbage
  // lines, then "framing rejected: <reason>" for each reason seen at least once.
  std::vector<std::pair<std::string, std::uint64_t>> counters() const;

private:
  FramerConfig config_;
  Sentence sentence_;
  std::uint64_t sentences_ = 0, garbage_ = 0;
  std::uint64_t rejects_[static_cast<std::size_t>(Reject::kCount)] = {};
};

}  // namespace asv::nmea
