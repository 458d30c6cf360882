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


// A choice between words: the word found, the default when absent, and a
// message listing every choice for anything else
TEST(dictionaryChecks, wordOfChoices)
{
    using namespace dictionaryChecks;
    const dictionary d = testHelpers::dictOf("s MUSL; t fast; u 3;");
    EXPECT_EQ(getWordOf(d, "s", "USL", {"USL", "MUSL"}), "MUSL");
    EXPECT_EQ(getWordOf(d, "missing", "USL", {"USL", "MUSL"}), "USL");

    std::string m = testHelpers::ioErrorOf
    (
        [&]{ getWordOf(d, "t", "slow", {"slow", "medium", "steady"}); }
    );
    EXPECT_NE(m.find("'t'"), std::string::npos) << m;
    EXPECT_NE(m.find("fast"), std::string::npos) << m;
    EXPECT_NE(m.find("slow, medium or steady"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([&]{ getWordOf(d, "u", "a", {"a", "b"}); });
    EXPECT_NE(m.find("'u'"), std::string::npos) << m;
    EXPECT_NE(m.find("a or b"), std::string::npos) << m;
}


// Entries that overflow the products of a model, lists of a negative size
// (OpenFOAM's List raises a FatalError "bad size", not a FatalIOError) and
// vectors with huge components all end in the message naming the entry
TEST(dictionaryChecks, boundsAndBadLists)
{
    using namespace dictionaryChecks;
    const dictionary d = testHelpers::dictOf
    (
        "a 1e300; b 0.5; w -1; v (1e300 0 0); u (1 2 3);"
    );
    EXPECT_DOUBLE_EQ(getInRange(d, "b", 0, 1), 0.5);
    EXPECT_DOUBLE_EQ(getInRange(d, "missing", 0.25, 0, 1), 0.25);
    EXPECT_EQ(getBoundedVector(d, "u", Zero, 10, "a vector"), vector(1, 2, 3));

    std::string m = testHelpers::ioErrorOf([&]{ getInRange(d, "a", 0, 1e30); });
    EXPECT_NE(m.find("'a'"), std::string::npos) << m;
    EXPECT_NE(m.find("1e+300"), std::string::npos) << m;
    EXPECT_NE(m.find("<= 1e+30"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([&]{ getAs<List<scalar>>(d, "w", "a list"); });
    EXPECT_NE(m.find("'w'"), std::string::npos) << m;
    EXPECT_NE(m.find("a list"), std::string::npos) << m;

    m = testHelpers::ioErrorOf([&]{ getBoundedVector(d, "v", Zero, 1e30, "a velocity"); });
    EXPECT_NE(m.find("'v'"), std::string::npos) << m;
    EXPECT_NE(m.find("magnitude <= 1e+30"), std::string::npos) << m;

    // FatalError is left as it was (not throwing)
    EXPECT_FALSE(FatalError.throwExceptions(false));
}
