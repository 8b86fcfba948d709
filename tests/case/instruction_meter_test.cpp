// The instruction meter's bookkeeping (outside callgrind its requests do nothing, so what is left to test is which
// parts it numbers): only parts ended inside a bracketed timed step count, numbered in order across meters.
#include "case/instruction_meter.h"

#include <gtest/gtest.h>

namespace tcsb {
namespace {

TEST(InstructionMeter, NumbersThePartsOfBracketedStepsOnly) {
  InstructionMeter meter, other;
  meter.end_part(StepPart::kOwn);  // a warm-up step: not counted
  meter.begin_step();
  meter.end_part(StepPart::kOwn);
  meter.end_part(StepPart::kBullet);
  meter.end_step();
  meter.end_part(StepPart::kOwn);  // after the step: not counted
  other.begin_step();
  other.end_part(StepPart::kBullet);
  other.end_step();
  ASSERT_EQ(meter.parts().size(), 2u);
  EXPECT_EQ(meter.parts()[0].part, StepPart::kOwn);
  EXPECT_EQ(meter.parts()[1].part, StepPart::kBullet);
  EXPECT_EQ(meter.parts()[1].dump, meter.parts()[0].dump + 1);
  ASSERT_EQ(other.parts().size(), 1u);
  EXPECT_EQ(other.parts()[0].dump, meter.parts()[1].dump + 1) << "one sequence per process, as callgrind's file";
}

}  // namespace
}  // namespace tcsb
