// NMEA 0183 framing: checksums, tag blocks, field splitting and every rejection reason. Checksums of
// hand-made sentences are computed here with a local XOR, independent of nmea::checksum.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "asv_core/codec/line_framer.h"
#include "asv_core/codec/nmea.h"

using namespace asv::nmea;

namespace {

std::string withChecksum(const std::string& start_and_body, bool lower = false) {
  unsigned x = 0;
  for (std::size_t i = 1; i < start_and_body.size(); ++i)
    x ^= static_cast<unsigned char>(start_and_body[i]);
  char hex[4];
  std::snprintf(hex, sizeof(hex), lower ? "%02x" : "%02X", x);
  return start_and_body + "*" + hex;
}

// "\content*hh\" with the tag-block checksum.
std::string tagBlock(const std::string& content, bool lower = false) {
  unsigned x = 0;
  for (char c : content)
    x ^= static_cast<unsigned char>(c);
  char hex[4];
  std::snprintf(hex, sizeof(hex), lower ? "%02x" : "%02X", x);
  return "\\" + content + "*" + hex + "\\";
}

const char* const kType1 = "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A";

}  // namespace

TEST(NmeaFraming, ParsesAivdmFields) {
  Sentence s;
  ASSERT_EQ(parseSentence(kType1, s), Reject::kNone);
  EXPECT_EQ(s.start, '!');
  EXPECT_EQ(s.talker, "AI");
  EXPECT_EQ(s.type, "VDM");
  EXPECT_TRUE(s.has_checksum);
  ASSERT_EQ(s.field_count, 7u);
  EXPECT_EQ(s.field(0), "AIVDM");
  EXPECT_EQ(s.field(1), "1");
  EXPECT_EQ(s.field(3), "");
  EXPECT_EQ(s.field(4), "A");
  EXPECT_EQ(s.field(5), "15RTgt0PAso;90TKcjM8h6g208CQ");
  EXPECT_EQ(s.field(6), "0");
  EXPECT_EQ(s.field(7), "");  // absent fields read as empty
  EXPECT_EQ(s.end, std::string(kType1).size());
  EXPECT_FALSE(s.tag.present);
  EXPECT_TRUE(s.suffix.empty());
}

TEST(NmeaFraming, ChecksumHexCaseInsensitive) {
  const std::string body = "$RATTM,01,2.5,045.0,T,12.0,180.0,T,0.5,10.0,N,TGT1,T,,123456.78,A";
  Sentence s;
  const std::string upper = withChecksum(body, false), lower = withChecksum(body, true);
  EXPECT_EQ(parseSentence(upper, s), Reject::kNone);
  EXPECT_EQ(parseSentence(lower, s), Reject::kNone);  // views into `lower`, which outlives them
  EXPECT_EQ(s.talker, "RA");
  EXPECT_EQ(s.type, "TTM");
  EXPECT_EQ(s.field_count, 16u);
  // "!AIVDM,1,1,,B,177KQJ5000G?tO`K>RA1wUbN0TKH,0*5c": lower-case hex from some receivers
  EXPECT_EQ(parseSentence("!AIVDM,1,1,,B,177KQJ5000G?tO`K>RA1wUbN0TKH,0*5c", s), Reject::kNone);
}

TEST(NmeaFraming, ChecksumErrors) {
  Sentence s;
  EXPECT_EQ(parseSentence("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4B", s), Reject::kBadChecksum);
  EXPECT_EQ(parseSentence("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0", s), Reject::kNoChecksum);
  EXPECT_EQ(parseSentence("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4", s), Reject::kBadChecksumFormat);
  EXPECT_EQ(parseSentence("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*", s), Reject::kBadChecksumFormat);
  EXPECT_EQ(parseSentence("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*G1", s), Reject::kBadChecksumFormat);
  // A line cut in the middle of the payload (a truncated serial read).
  EXPECT_EQ(parseSentence("!AIVDM,1,1,,A,15RTgt0PA", s), Reject::kNoChecksum);
  FramerConfig lenient;
  lenient.require_checksum = false;
  ASSERT_EQ(parseSentence("$GPGLL,4916.45,N,12311.12,W,225444,A", s, lenient), Reject::kNone);
  EXPECT_FALSE(s.has_checksum);
  EXPECT_EQ(s.field(1), "4916.45");
}

// The framer of every NMEA node: valid sentences pass on, the rest is counted by reason. Checksums by
// hand (XOR of the characters between ! and *): "AIVDM,1,1,,B,177KQJ5000G?tO`K>RA1wUbN0TKH,0" is 5C,
// "AIVDM,1,1,,A,15M67FC000G?ufbE`FepT@3n00Sa,0" is 5F (sent here with 5E, a one-bit error).
TEST(NmeaLineFramer, PassesValidSentencesAndCountsTheRestByReason) {
  const std::string good1 = "!AIVDM,1,1,,B,177KQJ5000G?tO`K>RA1wUbN0TKH,0*5C";
  const std::string good2 = "!AIVDM,1,1,,A,15M67FC000G?ufbE`FepT@3n00Sa,0*5F";
  const std::string bad = "!AIVDM,1,1,,A,15M67FC000G?ufbE`FepT@3n00Sa,0*5E";
  LineFramer framer;
  std::vector<std::string> passed;
  const auto keep = [&](const Sentence& s) { passed.emplace_back(s.field(5)); };
  framer.frame("noise " + good1 + good2, keep);  // two glued sentences after line noise
  framer.frame(good1 + " " + bad, keep);         // the broken one at the end costs nothing before it
  framer.frame("no sentence in this line", keep);
  framer.frame("   ", keep);  // blank (terminators are stripped before): neither sentence nor garbage
  ASSERT_EQ(passed.size(), 3u);
  EXPECT_EQ(passed[0], "177KQJ5000G?tO`K>RA1wUbN0TKH");
  EXPECT_EQ(passed[1], "15M67FC000G?ufbE`FepT@3n00Sa");
  EXPECT_EQ(passed[2], "177KQJ5000G?tO`K>RA1wUbN0TKH");
  EXPECT_EQ(framer.sentences(), 3u);
  EXPECT_EQ(framer.garbage(), 2u);  // "noise " and the line without a sentence
  EXPECT_EQ(framer.rejected(Reject::kBadChecksum), 1u);
  EXPECT_EQ(framer.checksumFailures(), 1u);
  EXPECT_EQ(framer.totalRejected(), 3u);
  const auto counters = framer.counters();
  ASSERT_EQ(counters.size(), 4u);  // the three totals and the one reason seen
  EXPECT_EQ(counters[0], std::make_pair(std::string("sentences framed"), uint64_t{3}));
  EXPECT_EQ(counters[2], std::make_pair(std::string("garbage lines"), uint64_t{2}));
  EXPECT_EQ(counters[3].first, std::string("framing rejected: ") + rejectText(Reject::kBadChecksum));
  EXPECT_EQ(counters[3].second, 1u);
}

TEST(NmeaFraming, LineTerminatorsAndWhitespace) {
  Sentence s;
  EXPECT_EQ(parseSentence(std::string(kType1) + "\r\n", s), Reject::kNone);
  EXPECT_EQ(parseSentence(std::string("  ") + kType1 + " \r", s), Reject::kNone);
  EXPECT_EQ(s.end, 2 + std::string(kType1).size());  // relative to the line as passed
  EXPECT_EQ(parseSentence("", s), Reject::kEmpty);
  EXPECT_EQ(parseSentence(" \r\n", s), Reject::kEmpty);
}

TEST(NmeaFraming, LengthLimit) {
  Sentence s;
  // Longer than the 82 of the standard but under the tolerated limit: accepted (type 5 in one line).
  const std::string long_ok =
      withChecksum("!AIVDM,1,1,,A,55?MbV02;H;s<HtKP00EHE:0@T4@Dl0000000016L961O5Gf0NSQEp6ClRh000000000000,2");
  ASSERT_GT(long_ok.size(), kStandardMaxLength);
  EXPECT_EQ(parseSentence(long_ok, s), Reject::kNone);
  const std::string too_long = withChecksum("!AIVDM,1,1,,A," + std::string(600, '0') + ",0");
  EXPECT_EQ(parseSentence(too_long, s), Reject::kTooLong);
  FramerConfig small;
  small.max_length = 82;
  EXPECT_EQ(parseSentence(long_ok, s, small), Reject::kTooLong);
}

TEST(NmeaFraming, RejectsBinaryAndNonPrintable) {
  Sentence s;
  std::string bin = kType1;
  bin[20] = '\x01';
  EXPECT_EQ(parseSentence(bin, s), Reject::kNonPrintable);
  bin = kType1;
  bin[10] = static_cast<char>(0xff);
  EXPECT_EQ(parseSentence(bin, s), Reject::kNonPrintable);
  EXPECT_EQ(parseSentence(std::string(kType1) + "\x02\x03", s), Reject::kNonPrintable);
  EXPECT_EQ(parseSentence(std::string("\0\x10\x80garbage", 10), s), Reject::kNoStart);
}

TEST(NmeaFraming, StartAndAddress) {
  Sentence s;
  EXPECT_EQ(parseSentence("AIVDM,2,2,1,B,00000000000,2*26", s), Reject::kNoStart);
  EXPECT_EQ(parseSentence(withChecksum("$,1,2"), s), Reject::kBadAddress);
  EXPECT_EQ(parseSentence(withChecksum("$A-VDM,1,2"), s), Reject::kBadAddress);
  const std::string proprietary = withChecksum("$PGRME,15.0,M,45.0,M,25.0,M");
  ASSERT_EQ(parseSentence(proprietary, s), Reject::kNone);
  EXPECT_EQ(s.talker, "P");
  EXPECT_EQ(s.type, "GRME");
  std::string many = "$GPXXX";
  for (int i = 0; i < 60; ++i)
    many += ",1";
  EXPECT_EQ(parseSentence(withChecksum(many), s), Reject::kTooManyFields);
}

TEST(NmeaFraming, UscgSuffixKept) {
  Sentence s;
  const std::string line =
      "!AIVDM,1,1,,A,15N1u<PP1FJuvSRHOE6QIwwh0HQ6,0*30,d-080,S2118,t050056.00,T56.4837741,r003669946,"
      "1325394060,1325394001";
  ASSERT_EQ(parseSentence(line, s), Reject::kNone);
  EXPECT_EQ(s.field(5), "15N1u<PP1FJuvSRHOE6QIwwh0HQ6");
  EXPECT_EQ(s.suffix.substr(0, 6), ",d-080");
  FramerConfig strict;
  strict.allow_suffix = false;
  EXPECT_EQ(parseSentence(line, s, strict), Reject::kBadChecksumFormat);
}

TEST(NmeaTagBlock, ParsesSourceTimeAndGroup) {
  Sentence s;
  // From libais test/data/tagblock.nmea.
  ASSERT_EQ(parseSentence("\\g:1-2-1604,s:rORBCOMM008,c:1418169601,T:2014-12-10 00.00.01*37\\!AIVDM,2,1,6,A,"
                          "53@o0E000001Q0CG37U8u<Tp4q@D00000000000018330400000000000000,0*63",
                          s),
            Reject::kNone);
  EXPECT_TRUE(s.tag.present);
  EXPECT_EQ(s.tag.source, "rORBCOMM008");
  EXPECT_TRUE(s.tag.has_time);
  EXPECT_DOUBLE_EQ(s.tag.unix_time, 1418169601.0);
  ASSERT_TRUE(s.tag.has_group);
  EXPECT_EQ(s.tag.group_sentence, 1);
  EXPECT_EQ(s.tag.group_count, 2);
  EXPECT_EQ(s.tag.group_id, 1604);
  EXPECT_EQ(s.type, "VDM");
  EXPECT_EQ(s.field(3), "6");

  ASSERT_EQ(parseSentence("\\s:rORBCOMM104,q:u,c:1418172113,T:2014-12-10 00.41.53*55\\!AIVDM,1,1,,B,"
                          "13F?Vv700<DJuLEtvep`iToV0<00,0*78",
                          s),
            Reject::kNone);
  EXPECT_EQ(s.tag.source, "rORBCOMM104");
  EXPECT_FALSE(s.tag.has_group);
  // Milliseconds in c: are recognised.
  ASSERT_EQ(parseSentence(tagBlock("c:1418172113000", true) + kType1, s), Reject::kNone);
  EXPECT_DOUBLE_EQ(s.tag.unix_time, 1418172113.0);
}

TEST(NmeaTagBlock, Rejections) {
  Sentence s;
  EXPECT_EQ(parseSentence(std::string("\\s:rORBCOMM104,c:1418172113*00\\") + kType1, s),
            Reject::kTagBlockChecksum);
  EXPECT_EQ(parseSentence(std::string("\\s:rORBCOMM104,c:1418172113\\") + kType1, s),
            Reject::kTagBlockChecksum);
  EXPECT_EQ(parseSentence("\\s:rORBCOMM104,c:141817", s), Reject::kBadTagBlock);
  EXPECT_EQ(parseSentence(tagBlock("g:3-2-1") + kType1, s), Reject::kBadTagBlock);
  EXPECT_EQ(parseSentence(tagBlock("c:12x") + kType1, s), Reject::kBadTagBlock);
  EXPECT_EQ(parseSentence(tagBlock("sx") + kType1, s), Reject::kBadTagBlock);
  // Tag block alone, no sentence behind it.
  EXPECT_EQ(parseSentence(tagBlock("s:r"), s), Reject::kNoStart);
}

TEST(NmeaResync, FindsSentenceAfterGarbage) {
  const std::string line = std::string("xx$%garbage") + kType1;
  const std::size_t p = findSentenceStart(line);
  ASSERT_NE(p, std::string::npos);
  // The first '$' is garbage; the resync must be retried after a failure.
  Sentence s;
  EXPECT_NE(parseSentence(std::string_view(line).substr(p), s), Reject::kNone);
  const std::size_t q = findSentenceStart(line, p + 1);
  ASSERT_NE(q, std::string::npos);
  EXPECT_EQ(parseSentence(std::string_view(line).substr(q), s), Reject::kNone);
  EXPECT_EQ(s.field(5), "15RTgt0PAso;90TKcjM8h6g208CQ");

  // A tag block in front of the sentence is kept with it.
  const std::string tagged = "noise \\s:rORBCOMM104,q:u,c:1418172113,T:2014-12-10 00.41.53*55\\!AIVDM";
  EXPECT_EQ(findSentenceStart(tagged), 6u);
  EXPECT_EQ(findSentenceStart("no sentence here"), std::string::npos);
}

TEST(NmeaNumbers, ParseWithPadding) {
  double d = -1;
  EXPECT_TRUE(parseDouble(" 12.50 ", d));
  EXPECT_DOUBLE_EQ(d, 12.5);
  EXPECT_TRUE(parseDouble("+3", d));
  EXPECT_DOUBLE_EQ(d, 3.0);
  EXPECT_TRUE(parseDouble("-0.25", d));
  EXPECT_DOUBLE_EQ(d, -0.25);
  EXPECT_FALSE(parseDouble("", d));
  EXPECT_FALSE(parseDouble("   ", d));
  EXPECT_FALSE(parseDouble("1.2.3", d));
  EXPECT_DOUBLE_EQ(d, -0.25);  // untouched on failure
  long n = 0;
  EXPECT_TRUE(parseInt(" 101", n));
  EXPECT_EQ(n, 101);
  EXPECT_FALSE(parseInt("1a", n));
}

TEST(NmeaConfig, Validate) {
  FramerConfig c;
  EXPECT_NO_THROW(c.validate());
  c.max_length = 10;
  EXPECT_THROW(c.validate(), std::invalid_argument);
  for (int r = 0; r < static_cast<int>(Reject::kCount); ++r)
    EXPECT_STRNE(rejectText(static_cast<Reject>(r)), "unknown");
}
