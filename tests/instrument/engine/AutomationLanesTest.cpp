// Automation files ("rosin-automation/1", rosin render --automation): every parameter the engine has can be
// automated, by its own unit, choice name or true/false; mistakes name the file, the field and what was
// expected.
#include <gtest/gtest.h>

#include "core/config/ConfigError.h"
#include "instrument/engine/AutomationLanes.h"
#include "instrument/engine/ParameterSet.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

TEST(AutomationLanes, EveryParameterCanBeAutomated)
{
    engine::ParameterSet p;
    nlohmann::json lanes = nlohmann::json::object();
    for (const char* id : engine::allParameterIds())
    {
        auto* parameter = p.find(id);
        ASSERT_NE(parameter, nullptr) << id;
        nlohmann::json value;
        if (auto* choice = dynamic_cast<juce::AudioParameterChoice*>(parameter))
            value = choice->choices[choice->choices.size() - 1].toStdString();
        else if (dynamic_cast<juce::AudioParameterBool*>(parameter) != nullptr)
            value = true;
        else
            value = parameter->getNormalisableRange().convertFrom0to1(0.5f);
        lanes[id] = nlohmann::json::array({nlohmann::json::array({0.0, value})});
    }
    const nlohmann::json root = {{"format", "rosin-automation/1"}, {"lanes", lanes}};
    const engine::AutomationLanes parsed = engine::parseAutomation(root, "all.json");
    ASSERT_EQ(parsed.lanes.size(), engine::allParameterIds().size());
    for (const auto& lane : parsed.lanes)
    {
        auto* parameter = p.find(lane.parameterId);
        if (auto* choice = dynamic_cast<juce::AudioParameterChoice*>(parameter))
            EXPECT_EQ(lane.valueAt(0.0), choice->choices.size() - 1) << lane.parameterId;
    }
}

TEST(AutomationLanes, MistakesNameTheFieldAndTheExpectation)
{
    auto message = [](const nlohmann::json& lanes)
    {
        try
        {
            engine::parseAutomation({{"format", "rosin-automation/1"}, {"lanes", lanes}}, "take.json");
        }
        catch (const config::ConfigError& e)
        {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message({{"bowForse", {{0, 1.0}}}})
                  .find("take.json: field \"lanes.bowForse\": expected a parameter ID"),
              std::string::npos);
    EXPECT_NE(message({{"output", {{0, "loud"}}}}).find("field \"lanes.output[0]\""), std::string::npos);
    EXPECT_NE(message({{"bowForce", {{1.0, 1.0}, {0.5, 1.0}}}}).find("not before the previous point"),
              std::string::npos);
    EXPECT_NE(message({{"beta", {{0, 0.9}}}}).find("field \"lanes.beta[0]\": expected a value in"),
              std::string::npos);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
