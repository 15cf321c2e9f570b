// AIS decoding throughput. BM_AisDecode: type 1 sentences through framing, checksum, armour and field
// extraction, one item per sentence (goal: >= 2 million sentences/s per core).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/arpa.h"
#include "asv_core/codec/nmea.h"

namespace {

// Real type 1/3 sentences from gpsd's sample.aivdm and libais's examples, so the branch pattern is
// not a single repeated input.
const std::vector<std::string>& type1Sentences() {
  static const std::vector<std::string> s = {
      "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A", "!AIVDM,1,1,,A,16SteH0P00Jt63hHaa6SagvJ087r,0*42",
      "!AIVDM,1,1,,B,25Cjtd0Oj;Jp7ilG7=UkKBoB0<06,0*60", "!AIVDM,1,1,,A,38Id705000rRVJhE7cl9n;160000,0*40",
      "!AIVDM,1,1,,A,13aIkM@P00PJ@qPNL=e@0?wJ28JO,0*66", "!AIVDM,1,1,,B,13F?Vv700<DJuLEtvep`iToV0<00,0*78",
      "!AIVDM,1,1,,A,15N1u<PP1FJuvSRHOE6QIwwh0HQ6,0*30", "!AIVDM,1,1,,B,3Neq`dE5?vd;EsQUugH>3s>HR30q,0*6E",
  };
  return s;
}

void BM_AisDecode(benchmark::State& state) {
  const auto& lines = type1Sentences();
  asv::ais::Decoder decoder;
  asv::nmea::Sentence sentence;
  asv::ais::Message message;
  std::size_t i = 0;
  std::uint64_t sum = 0;
  for (auto _ : state) {
    const std::string& line = lines[i];
    i = (i + 1) % lines.size();
    if (asv::nmea::parseSentence(line, sentence) != asv::nmea::Reject::kNone)
      state.SkipWithError("framing");
    if (decoder.feed(sentence, 0.0, message) != asv::ais::Status::kMessage)
      state.SkipWithError("decode");
    sum += message.mmsi;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_AisDecode);

// Framing alone (checksum and field split), for comparison.
void BM_NmeaFrame(benchmark::State& state) {
  const auto& lines = type1Sentences();
  asv::nmea::Sentence sentence;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(asv::nmea::parseSentence(lines[i], sentence));
    i = (i + 1) % lines.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_NmeaFrame);

// Two-fragment type 5, one item per message.
void BM_AisDecodeType5(benchmark::State& state) {
  const std::string p1 = "!AIVDM,2,1,3,A,55?MbV02;H;s<HtKP00EHE:0@T4@Dl0000000016L961O5Gf0NSQEp6ClRh0,0*0C";
  const std::string p2 = "!AIVDM,2,2,3,A,00000000000,2*27";
  asv::ais::Decoder decoder;
  asv::ais::Message message;
  for (auto _ : state) {
    decoder.feedLine(p1, 0.0, message);
    if (decoder.feedLine(p2, 0.0, message) != asv::ais::Status::kMessage)
      state.SkipWithError("decode");
    benchmark::DoNotOptimize(message.mmsi);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_AisDecodeType5);

void BM_ArpaTtm(benchmark::State& state) {
  const std::string line = "$RATTM,01,2.50,045.0,T,12.0,180.0,T,0.50,-5.5,N,TGT1,T,,123456.78,A*6C";
  asv::nmea::Sentence sentence;
  asv::arpa::TrackedTarget target;
  for (auto _ : state) {
    if (asv::nmea::parseSentence(line, sentence) != asv::nmea::Reject::kNone)
      state.SkipWithError("framing");
    benchmark::DoNotOptimize(asv::arpa::parseTtm(sentence, target));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_ArpaTtm);

}  // namespace

BENCHMARK_MAIN();
