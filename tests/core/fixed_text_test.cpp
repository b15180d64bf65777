// fixed_text (src/core/fixed_text.h) replaced snprintf("%.*f") in the decision reasons and reports:
// it must print exactly the same text.
#include "core/fixed_text.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

std::string printf_text(double v, int decimals) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

TEST(FixedText, PrintsLikePrintfOnEdgeCases) {
  for (const double v : {0.0, -0.0, 0.125, 0.375, 2.5, -2.675, 1e-7, 33.34, 1e21, -1e300,
                         std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(), std::nan("")})
    for (int decimals = 0; decimals <= 6; ++decimals)
      EXPECT_EQ(fixed_text(v, decimals), printf_text(v, decimals)) << v << " with " << decimals << " decimals";
}

RC_GTEST_PROP(FixedText, PrintsLikePrintf, ()) {
  const double v = *rc::gen::arbitrary<double>();
  const int decimals = *rc::gen::inRange(0, 7);
  RC_ASSERT(fixed_text(v, decimals) == printf_text(v, decimals));
}

}  // namespace
}  // namespace mg
