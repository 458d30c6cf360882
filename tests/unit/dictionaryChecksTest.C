// Unit tests of the dictionary checks behind every mpmFoam FatalIOError

#include "dictionaryChecks.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{
enum class colour { red, green };
const Enum<colour> colourNames({{colour::red, "red"}, {colour::green, "green"}});

dictionary dictOf(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

// The FatalIOError message of f(), or "" if it did not stop
template<class F>
std::string errorOf(F f)
{
    FatalIOError.throwExceptions();
    std::string msg;
    try
    {
        f();
    }
    catch (const Foam::IOerror& err)
    {
        msg = err.message();
    }
    FatalIOError.dontThrowExceptions();
    return msg;
}
}


TEST(dictionaryChecks, goodValuesAndDefaults)
{
    const dictionary d = dictOf("n 4; x 0.5; c green; flag yes;");
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
    const dictionary d = dictOf("n 0; s word; x -2; c blue;");

    std::string m = errorOf([&]{ getLabelAtLeast(d, "n", 1, 1); });
    EXPECT_NE(m.find("'n'"), std::string::npos) << m;
    EXPECT_NE(m.find("an integer >= 1"), std::string::npos) << m;

    m = errorOf([&]{ getLabelAtLeast(d, "s", 1, 1); });
    EXPECT_NE(m.find("'s'"), std::string::npos) << m;
    EXPECT_NE(m.find("word"), std::string::npos) << m;

    m = errorOf([&]{ getPositive(d, "x", 1); });
    EXPECT_NE(m.find("'x'"), std::string::npos) << m;
    EXPECT_NE(m.find("> 0"), std::string::npos) << m;

    m = errorOf([&]{ getEnum(d, "c", colourNames, colour::red); });
    EXPECT_NE(m.find("blue"), std::string::npos) << m;
    EXPECT_NE(m.find("green"), std::string::npos) << m;

    m = errorOf([&]{ getAs<scalar>(d, "missing", "a number"); });
    EXPECT_NE(m.find("'missing' is missing"), std::string::npos) << m;
}
