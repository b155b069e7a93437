#include <gtest/gtest.h>

#include "core/hand/hand_frame.h"

namespace lmc {
namespace hand_point_words_test {

TEST(HandPointWords, NameTheFingerAndKeepTheFilesName) {
  const int ring_tip = *hand_point_from_name("Finger4_End");
  EXPECT_EQ(hand_point_words(ring_tip), "ring finger tip (Finger4_End)");
  EXPECT_EQ(hand_point_words(*hand_point_from_name("Finger1_Proxi")), "thumb knuckle (Finger1_Proxi)");
  EXPECT_EQ(hand_point_words(*hand_point_from_name("Finger2_Inter")), "index finger middle joint (Finger2_Inter)");
  EXPECT_EQ(hand_point_words(*hand_point_from_name("Palm Position")), "palm position");
  EXPECT_EQ(hand_point_words(-1), "");
  EXPECT_EQ(hand_point_words(kNumHandPoints), "");
}

}  // namespace hand_point_words_test
}  // namespace lmc
