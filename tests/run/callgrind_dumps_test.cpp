// Reading the meter's dumps from callgrind's combined output: each "tcsb-part N" dump's summary and its functions'
// own instructions (a call's inclusive cost is not its caller's own), other dumps skipped.
#include "run/callgrind_dumps.h"

#include <gtest/gtest.h>

#include <sstream>

namespace tcsb {
namespace {

// The shape callgrind 3.19 writes with --combine-dumps=yes --compress-strings=no --compress-pos=no.
constexpr const char* kFile = R"(# callgrind format
version: 1
creator: callgrind-3.19.0
cmd: tcsb run
part: 1

desc: Timerange: Basic block 0 - 100
desc: Trigger: Client Request: tcsb-part 0

positions: line
events: Ir
summary: 623

ob=/tmp/tcsb
fl=???
fn=main
0 13
cfn=g
calls=1 0
0 600
fn=g
0 10

totals: 623

part: 2

desc: Trigger: Client Request: tcsb-part 1

positions: line
events: Ir
summary: 50

fn=g
5 50

part: 3

desc: Trigger: Program termination

positions: line
events: Ir
summary: 9999

fn=exit
0 9999
)";

MeterDumps parse(const std::string& text) {
  std::istringstream in(text);
  return parse_meter_dumps(in, "cg.out");
}

TEST(CallgrindDumps, ReadsEachMeterDumpsSummaryAndOwnCosts) {
  const MeterDumps d = parse(kFile);
  ASSERT_EQ(d.dumps.size(), 2u);
  ASSERT_TRUE(d.dumps[0] && d.dumps[1]);
  EXPECT_EQ(d.dumps[0]->instructions, 623u);
  EXPECT_EQ(d.dumps[1]->instructions, 50u);
  std::map<std::string, std::uint64_t> own;
  for (const auto& [name, cost] : d.dumps[0]->functions) own[d.names[name]] = cost;
  EXPECT_EQ(own["main"], 13u) << "the call's 600 are g's, not main's own";
  EXPECT_EQ(own["g"], 10u);
  EXPECT_EQ(own.count("exit"), 0u) << "the program-end dump is not the meter's";
}

TEST(CallgrindDumps, CompressedNamesAreResolved) {
  const MeterDumps d =
      parse("part: 1\ndesc: Trigger: Client Request: tcsb-part 0\npositions: line\nsummary: 7\nfn=(1) f\n0 3\n"
            "part: 2\ndesc: Trigger: Client Request: tcsb-part 1\nsummary: 4\nfn=(1)\n0 4\n");
  ASSERT_EQ(d.names.size(), 1u);
  EXPECT_EQ(d.names[0], "f");
  EXPECT_EQ(d.dumps[1]->functions.at(0).second, 4u);
}

TEST(CallgrindDumps, MalformedLinesAreErrorsNamingTheFile) {
  EXPECT_THROW(parse("part: 1\ndesc: Trigger: Client Request: tcsb-part x\n"), CallgrindFileError);
  EXPECT_THROW(parse("part: 1\ndesc: Trigger: Client Request: tcsb-part 0\n0 5\n"), CallgrindFileError);
  EXPECT_THROW(parse("part: 1\ndesc: Trigger: Client Request: tcsb-part 0\npart: 2\n"
                     "desc: Trigger: Client Request: tcsb-part 0\n"),
               CallgrindFileError);
  EXPECT_THROW(read_meter_dumps("/nonexistent/cg.out"), CallgrindFileError);
}

}  // namespace
}  // namespace tcsb
