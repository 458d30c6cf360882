// Unit tests of the dictionary checks behind every mpmFoam FatalIOError

#include "dictionaryChecks.H"
#include "testHelpers.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{
enum class colour { red, green };
const Enum<colour> colourNames({{colour::red, "red"}, {colour::green, "green"}});

}


TEST(dictionaryChecks, goodValuesAndDefaults)
{
    const dictionary d = testHelpers::dictOf("n 4; x 0.5; c green; flag yes;");
    using namespace dictionaryChecks;
    EXPECT_EQ(getLabelAtLeast(d, "n", 1, 1), 4);
    EXPECT_EQ(getLabelAtLeast(d, "m", 7, 1), 7);
    EXPECT_DOUBLE_EQ(getPositive(d, "x", 1), 0.5);
    EXPECT_EQ(getEnum(d, "c", colourNames, colour::red), colour::green);
    EXPECT_EQ(getEnum(d, "d", colourNames, colour::red), colour::red);
    EXPECT_TRUE(getAsOrDefault<bool>(d, "flag", false, "true or false"));
}


TEST(dictionaryChecks, messagesNameEntryValueAndAllowed)
{
    using namespace dictionaryChecks;
    const dictionary d = testHelpers::dictOf("n 0; s word; x -2; c blue;");

    std::string m = testHelpers::ioErrorOf([&]{ getLabelAtLeast(d, "n", 1, 1); });
    EXPECT_NE(m.find("'n'"), std::string::npos) << m;
    EXPECT_NE(m.find("an integer >= 1"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([&]{ getLabelAtLeast(d, "s", 1, 1); });
    EXPECT_NE(m.find("'s'"), std::string::npos) << m;
    EXPECT_NE(m.find("word"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([&]{ getPositive(d, "x", 1); });
    EXPECT_NE(m.find("'x'"), std::string::npos) << m;
    EXPECT_NE(m.find("> 0"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([&]{ getEnum(d, "c", colourNames, colour::red); });
    EXPECT_NE(m.find("blue"), std::string::npos) << m;
    EXPECT_NE(m.find("green"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([&]{ getAs<scalar>(d, "missing", "a number"); });
    EXPECT_NE(m.find("'missing' is missing"), std::string::npos) << m;
}
