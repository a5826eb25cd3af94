#include "lab/discovery/RigReader.h"

#include "lab/discovery/FieldChecks.h"
#include "lab/discovery/StringFields.h"

namespace rosin::discovery
{

using config::JsonObject;

namespace
{
physics::StringParameters parseString(const JsonObject& s, std::vector<std::string>& defaulted)
{
    physics::StringParameters p = physics::stringFromCatalogue(kDefaultString);
    for (const auto& field : stringFields())
    {
        if (field.required)
            p.*field.member = requiredNumber(s, field.name, field.range);
        else if (const auto value = optionalNumber(s, field.name, field.range))
            p.*field.member = *value;
        else
            defaulted.emplace_back(field.name);
    }
    // The dataset gives the vibrating length, stopped or not, and one loss: the model bows it as an open
    // string, so the stopped loss must not differ.
    p.stoppedLossF = p.lossF;
    p.name = "measured";
    p.source = s.file() + " rig.string";
    return p;
}
} // namespace

Rig parseRig(const JsonObject& root)
{
    const JsonObject r = root.object("rig");
    Rig rig;
    rig.string = parseString(r.object("string"), rig.defaultedStringFields);
    if ((rig.body = r.optionalString("body")) && rig.body->empty())
        r.fail("body", "\"cello\", \"rigid\" or the path of a body description", "an empty string");
    if (r.has("bow"))
        rig.bow = r.at("bow");
    rig.ambientTemperature = optionalNumber(r, "ambientTemperature", kCelsius);
    return rig;
}

} // namespace rosin::discovery
