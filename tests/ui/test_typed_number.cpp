// The number typed into a modal tool: digits, point, minus and exponent as text, Backspace, and its
// value or NaN while it is not yet a number.
#include "ui/tools/typed_number.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cmath>
#include "tests/support/typed_events.h"

namespace gps {
namespace {

using test::key_event;
using test::text_event;

TEST(TypedNumber, DigitsPointAndMinusMakeTheValue) {
  TypedNumber typed;
  EXPECT_TRUE(typed.empty());
  EXPECT_TRUE(std::isnan(typed.value()));
  for (const char c : std::string("-0.25")) EXPECT_TRUE(typed.handle(text_event(c)));
  EXPECT_EQ(typed.text(), "-0.25");
  EXPECT_EQ(typed.value(), -0.25);
  EXPECT_EQ(typed.shown(), "  [-0.25]");
}

TEST(TypedNumber, OtherCharactersAndKeysAreNotTaken) {
  TypedNumber typed;
  EXPECT_FALSE(typed.handle(text_event('x')));
  EXPECT_FALSE(typed.handle(text_event('e')));  // an exponent needs a digit before it
  EXPECT_FALSE(typed.handle(key_event(GLFW_KEY_ENTER)));
  EXPECT_FALSE(typed.handle(key_event(GLFW_KEY_BACKSPACE)));  // nothing to take back
  EXPECT_TRUE(typed.empty());
  EXPECT_EQ(typed.shown(), "");
}

// "1e9" is a billion, not 19: the exponent once, after a digit (it was dropped, leaving "19").
TEST(TypedNumber, AnExponentAfterADigitIsTaken) {
  TypedNumber typed;
  for (const char c : std::string("1e9")) EXPECT_TRUE(typed.handle(text_event(c)));
  EXPECT_EQ(typed.value(), 1e9);
  EXPECT_FALSE(typed.handle(text_event('e')));
  TypedNumber small;
  for (const char c : std::string("2.5e-3")) EXPECT_TRUE(small.handle(text_event(c)));
  EXPECT_EQ(small.value(), 2.5e-3);
}

TEST(TypedNumber, BackspaceTakesTheLastCharacterBack) {
  TypedNumber typed;
  for (const char c : std::string("12")) typed.handle(text_event(c));
  EXPECT_TRUE(typed.handle(key_event(GLFW_KEY_BACKSPACE)));
  EXPECT_EQ(typed.value(), 1.0);
  EXPECT_TRUE(typed.handle(key_event(GLFW_KEY_BACKSPACE)));
  EXPECT_TRUE(typed.empty());
  EXPECT_TRUE(std::isnan(typed.value()));
}

TEST(TypedNumber, TextThatIsNotYetANumberIsNaN) {
  for (const std::string partial : {"-", ".", "-.", "1-", "1.2.3", "--1"}) {
    TypedNumber typed;
    for (const char c : partial) typed.handle(text_event(c));
    EXPECT_EQ(typed.text(), partial);
    EXPECT_TRUE(std::isnan(typed.value())) << partial;
  }
  TypedNumber point_five;
  for (const char c : std::string(".5")) point_five.handle(text_event(c));
  EXPECT_EQ(point_five.value(), 0.5);
}

}  // namespace
}  // namespace gps
