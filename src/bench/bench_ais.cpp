// AIS decoding throughput. BM_AisDecode: type 1 sentences through framing, checksum, armour and field
// extraction, one item per sentence (goal: >= 2 million sentences/s per core). BM_AisDecodeEveryType
// and BM_AisJsonEveryType: one message of each of the 27 types (and of the type 6/8 application
// payloads gpsd decodes), decoded, then also written as gpsd-format JSON.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/ais_json.h"
#include "asv_core/codec/arpa.h"
#include "asv_core/codec/json_out.h"
#include "asv_core/codec/nmea.h"
#include "asv_core/codec/nmea_encode.h"

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

// One message per type (random bits of a length every decoder accepts, header set; types 6 and 8
// with the application ids of the meteorological, tidal and inland messages), as sentence lines.
const std::vector<std::vector<std::string>>& everyTypeMessages() {
  struct Shape {
    unsigned type, bits;
    int dac, fid;
  };
  static const Shape kShapes[] = {
      {1, 168, -1, -1},  {2, 168, -1, -1},  {3, 168, -1, -1},  {4, 168, -1, -1},  {5, 424, -1, -1},
      {6, 360, 1, 12},   {6, 280, 1, 32},   {6, 136, 235, 10}, {6, 200, 366, 1},  {7, 168, -1, -1},
      {8, 352, 1, 11},   {8, 360, 1, 31},   {8, 168, 200, 10}, {8, 256, 366, 56}, {9, 168, -1, -1},
      {10, 72, -1, -1},  {11, 168, -1, -1}, {12, 300, -1, -1}, {13, 168, -1, -1}, {14, 200, -1, -1},
      {15, 160, -1, -1}, {16, 144, -1, -1}, {17, 400, -1, -1}, {18, 168, -1, -1}, {19, 312, -1, -1},
      {20, 160, -1, -1}, {21, 272, -1, -1}, {22, 168, -1, -1}, {23, 160, -1, -1}, {24, 168, -1, -1},
      {25, 168, -1, -1}, {26, 400, -1, -1}, {27, 96, -1, -1}};
  static const std::vector<std::vector<std::string>> messages = [] {
    std::mt19937 rng(7);
    std::vector<std::vector<std::string>> out;
    for (const Shape& s : kShapes) {
      asv::ais::BitWriter w;
      w.put(s.type, 6);
      w.put(0, 2);
      w.put(rng() & 0x3FFFFFFFu, 30);
      for (unsigned k = 38; k < s.bits; ++k) {
        if (s.dac >= 0 && k == (s.type == 6 ? 72u : 40u)) {
          w.put(static_cast<std::uint32_t>(s.dac), 10);
          w.put(static_cast<std::uint32_t>(s.fid), 6);
          k += 15;
          continue;
        }
        // Type 24: part B (1), so every message prints.
        w.put(s.type == 24 && k == 38 ? 0 : (s.type == 24 && k == 39 ? 1 : rng() & 1u), 1);
      }
      out.push_back(asv::ais::toSentences(w, 'A', static_cast<int>(out.size() % 10)));
    }
    return out;
  }();
  return messages;
}

// Decodes every message of everyTypeMessages(); `json` also writes both JSON forms of the fields.
void decodeEveryType(benchmark::State& state, bool json) {
  const auto& messages = everyTypeMessages();
  asv::ais::Decoder decoder;
  asv::ais::Message message;
  asv::json::Out out(nullptr);
  std::size_t i = 0;
  for (auto _ : state) {
    asv::ais::Status st = asv::ais::Status::kPending;
    for (const auto& line : messages[i])
      st = decoder.feedLine(line, 0.0, message);
    if (st != asv::ais::Status::kMessage)
      state.SkipWithError("decode");
    if (json) {
      out.clear();
      out.reserveRecord(0);
      asv::ais::AisFields w(out, (i & 1) != 0);
      asv::ais::writePayloadFields(decoder.payload(), w);
      benchmark::DoNotOptimize(out.text().data());
    }
    benchmark::DoNotOptimize(message.mmsi);
    i = (i + 1) % messages.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_AisDecodeEveryType(benchmark::State& state) {
  decodeEveryType(state, false);
}
BENCHMARK(BM_AisDecodeEveryType);

void BM_AisJsonEveryType(benchmark::State& state) {
  decodeEveryType(state, true);
}
BENCHMARK(BM_AisJsonEveryType);

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
