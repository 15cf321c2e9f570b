#include "asv_core/codec/line_framer.h"

namespace asv::nmea {

void LineFramer::frame(std::string_view line, const std::function<void(const Sentence&)>& on_sentence) {
  if (trim(line).empty())
    return;
  std::size_t pos = 0;
  bool any = false;
  while (pos < line.size()) {
    const std::size_t start = findSentenceStart(line, pos);
    if (start == std::string_view::npos)
      break;
    if (start > pos && !trim(line.substr(pos, start - pos)).empty())
      ++garbage_;
    any = true;
    const Reject r = parseSentence(line.substr(start), sentence_, config_);
    if (r == Reject::kNone) {
      ++sentences_;
      on_sentence(sentence_);
      // Receiver metadata after the checksum is a suffix, not garbage: go to the next start.
      const std::size_t next = findSentenceStart(line, start + sentence_.end);
      if (next == std::string_view::npos)
        break;
      pos = next;
      continue;
    }
    ++rejects_[static_cast<std::size_t>(r)];
    pos = start + 1;
  }
  if (!any)
    ++garbage_;
}

std::uint64_t LineFramer::checksumFailures() const {
  return rejected(Reject::kNoChecksum) + rejected(Reject::kBadChecksumFormat) +
         rejected(Reject::kBadChecksum) + rejected(Reject::kTagBlockChecksum);
}

std::uint64_t LineFramer::totalRejected() const {
  std::uint64_t n = garbage_;
  for (std::size_t i = 1; i < static_cast<std::size_t>(Reject::kCount); ++i)
    n += rejects_[i];
  return n;
}

std::vector<std::pair<std::string, std::uint64_t>> LineFramer::counters() const {
  std::vector<std::pair<std::string, std::uint64_t>> out = {{"sentences framed", sentences_},
                                                            {"checksum failures", checksumFailures()},
                                                            {"garbage lines", garbage_}};
  for (std::size_t i = 1; i < static_cast<std::size_t>(Reject::kCount); ++i)
    if (rejects_[i] > 0)
      out.emplace_back(std::string("framing rejected: ") + rejectText(static_cast<Reject>(i)), rejects_[i]);
  return out;
}

}  // namespace asv::nmea
