// Labels of fit series: distinct series never share a label; the added words name the
// parameters that differ, as the parameter table spells them and in its order.
#include <gtest/gtest.h>

#include "reports/series_labels.h"

namespace beverloo {
namespace {
using nlohmann::json;

TEST(SeriesLabels, DistinctLabelsAreLeftAlone) {
  std::vector<std::string> labels = {"a", "b"};
  disambiguate_labels(labels, {json{{"mu", 1.0}}, json{{"mu", 2.0}}});
  EXPECT_EQ(labels, (std::vector<std::string>{"a", "b"}));
}

TEST(SeriesLabels, CollidingLabelsNameEveryDifferingParameterInTableOrder) {
  std::vector<std::string> labels = {"2D SP", "2D SP", "other"};
  const json a = {{"E_sp", 100.0}, {"N", 1600}, {"reinjection", {{"rule", "lanes"}}}, {"W", 50.0}};
  json b = a;
  b["reinjection"].erase("rule");  // omitted at its default: shown as the default
  b["N"] = 800;
  disambiguate_labels(labels, {a, b, a});
  EXPECT_EQ(labels[0], "2D SP N=1600 reinjection.rule=lanes");
  EXPECT_EQ(labels[1], "2D SP N=800 reinjection.rule=pile");
  EXPECT_EQ(labels[2], "other");
}

}  // namespace
}  // namespace beverloo
