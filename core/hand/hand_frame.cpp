#include "core/hand/hand_frame.h"

#include <array>
#include <cctype>
#include <string>

namespace lmc {
namespace {

constexpr std::array<std::string_view, kNumHandPoints> kNames = {
    "Palm Position", "Palm Normal",   "Palm Direction", "Arm Proximal",  "Arm Distal",    "Finger1_Meta",
    "Finger1_Proxi", "Finger1_Inter", "Finger1_Dist",   "Finger1_End",   "Finger2_Meta",  "Finger2_Proxi",
    "Finger2_Inter", "Finger2_Dist",  "Finger2_End",    "Finger3_Meta",  "Finger3_Proxi", "Finger3_Inter",
    "Finger3_Dist",  "Finger3_End",   "Finger4_Meta",   "Finger4_Proxi", "Finger4_Inter", "Finger4_Dist",
    "Finger4_End",   "Finger5_Meta",  "Finger5_Proxi",  "Finger5_Inter", "Finger5_Dist",  "Finger5_End",
};

constexpr std::array<std::string_view, kNumDigits> kDigitNames = {"thumb", "index", "middle", "ring", "pinky"};

}  // namespace

std::string_view hand_point_name(int i) {
  if (i < 0 || i >= kNumHandPoints) return {};
  return kNames[static_cast<size_t>(i)];
}

std::optional<int> hand_point_from_name(std::string_view name) {
  for (int i = 0; i < kNumHandPoints; ++i) {
    if (kNames[static_cast<size_t>(i)] == name) return i;
  }
  return std::nullopt;
}

std::string hand_point_words(int i) {
  if (i < 0 || i >= kNumHandPoints) return {};
  constexpr int kFirstFingerPoint = 5;
  constexpr std::array<std::string_view, 5> kSegmentWords = {"base", "knuckle", "middle joint", "last joint", "tip"};
  if (i < kFirstFingerPoint) {
    std::string words(kNames[static_cast<size_t>(i)]);
    for (auto& c : words) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return words;
  }
  const int digit = (i - kFirstFingerPoint) / 5, segment = (i - kFirstFingerPoint) % 5;
  std::string words(kDigitNames[static_cast<size_t>(digit)]);
  if (digit > 0) words += " finger";
  return words + " " + std::string(kSegmentWords[static_cast<size_t>(segment)]) + " (" +
         std::string(kNames[static_cast<size_t>(i)]) + ")";
}

std::string_view digit_name(int digit) {
  if (digit < 0 || digit >= kNumDigits) return {};
  return kDigitNames[static_cast<size_t>(digit)];
}

}  // namespace lmc
