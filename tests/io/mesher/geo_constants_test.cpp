// The parameters a .geo declares with DefineConstant, read from its text: plain and ONELAB forms,
// several per bracket, comments and strings skipped, assignments that are not declarations left out.
#include <gtest/gtest.h>

#include "io/mesher/geo_constants.hpp"

namespace saasgaps::io {
namespace {

using Names = std::vector<std::string>;

TEST(GeoConstants, PlainAndOnelabFormsInOrder) {
  EXPECT_EQ(geo_constants("DefineConstant[ wall = 0.5, lc = {0.1, Name \"Parameters/lc\", Min 0, Max 1} ];\n"
                          "DefineConstant[d=1e-3];"),
            (Names{"wall", "lc", "d"}));
  // Expressions and nested brackets in a default; a name declared twice is listed once.
  EXPECT_EQ(geo_constants("DefineConstant[ a = Sqrt(2) * {1}[0], b = (1 + 2) ];\nDefineConstant[a = 3];"),
            (Names{"a", "b"}));
}

TEST(GeoConstants, CommentsStringsAndAssignmentsAreNotDeclarations) {
  EXPECT_EQ(geo_constants("// DefineConstant[ x = 1 ];\n/* DefineConstant[ y = 2 ]; */\n"
                          "Printf(\"DefineConstant[ z = 3 ]\");\nh = 0.2; DefineConstant[ w = 4 ];"),
            (Names{"w"}));
  EXPECT_TRUE(geo_constants("a = 1; b = 2;").empty());
  EXPECT_TRUE(geo_constants("DefineConstant").empty());
  EXPECT_TRUE(geo_constants("DefineConstant[ unclosed = 1").size() == 1);
}

TEST(GeoConstants, Identifiers) {
  EXPECT_TRUE(geo_identifier("wall"));
  EXPECT_TRUE(geo_identifier("_d2"));
  EXPECT_FALSE(geo_identifier("2d"));
  EXPECT_FALSE(geo_identifier(""));
  EXPECT_FALSE(geo_identifier("a-b"));
  EXPECT_FALSE(geo_identifier("a b"));
}

}  // namespace
}  // namespace saasgaps::io
