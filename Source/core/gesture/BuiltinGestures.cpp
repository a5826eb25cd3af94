#include "core/gesture/BuiltinGestures.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <vector>

#include "core/gesture/GestureLimits.h"

namespace rosin::gesture
{

namespace
{
struct Key
{
    const char* name;
    double defaultValue;
    Range range;
};

struct Builtin
{
    const char* name;
    const char* summary;
    std::vector<Key> keys; // in the order the help prints them
};

const std::vector<Builtin>& builtins()
{
    static const std::vector<Builtin> table = {
        {"steady",
         "bow at constant speed from t = 0",
         {{"speed", 0.05, limits::speed},
          {"force", 1.0, limits::force},
          {"beta", 0.1, limits::beta},
          {"seconds", 1.0, limits::seconds},
          {"finger", 1.0, limits::finger}}},
        {"guettler",
         "constant bow acceleration from rest (Guettler's gesture)",
         {{"acceleration", 1.56, limits::acceleration},
          {"force", 1.0, limits::force},
          {"beta", 0.0899, limits::beta},
          {"seconds", 0.5, limits::seconds},
          {"finger", 1.0, limits::finger}}},
    };
    return table;
}

const Builtin* findBuiltin(const std::string& name)
{
    for (const auto& b : builtins())
        if (name == b.name)
            return &b;
    return nullptr;
}

std::string keyList(const Builtin& b)
{
    std::string list;
    for (const auto& k : b.keys)
        list += (list.empty() ? "" : ", ") + std::string(k.name);
    return list;
}

double parseNumber(const std::string& field, const std::string& text)
{
    double value = 0.0;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    const auto result = std::from_chars(first, last, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != last)
        throw GestureError(field, "a number", "\"" + text + "\"");
    return value;
}
} // namespace

bool isBuiltinGestureSpec(const std::string& spec)
{
    const std::string name = spec.substr(0, spec.find(':'));
    return findBuiltin(name) != nullptr;
}

GestureScript parseBuiltinGesture(const std::string& spec)
{
    const auto colon = spec.find(':');
    const std::string name = spec.substr(0, colon);
    const Builtin* builtin = findBuiltin(name);
    if (builtin == nullptr)
        throw GestureError("gesture", "steady[:key=value,...] or guettler[:key=value,...]",
                           "\"" + name + "\"");

    std::map<std::string, double> values;
    for (const auto& k : builtin->keys)
        values[k.name] = k.defaultValue;

    if (colon != std::string::npos)
    {
        const std::string list = spec.substr(colon + 1);
        std::size_t pos = 0;
        while (pos <= list.size())
        {
            const std::size_t comma = std::min(list.find(',', pos), list.size());
            const std::string item = list.substr(pos, comma - pos);
            pos = comma + 1;
            if (item.empty())
                continue; // tolerate "steady:" and trailing commas
            const auto eq = item.find('=');
            const std::string key = item.substr(0, eq);
            if (values.count(key) == 0)
                throw GestureError(key, "one of the " + name + " keys " + keyList(*builtin),
                                   "\"" + key + "\"");
            if (eq == std::string::npos)
                throw GestureError(key, "key=value", "\"" + item + "\"");
            values[key] = parseNumber(key, item.substr(eq + 1));
        }
    }
    for (const auto& k : builtin->keys)
        requireInRange(k.name, values[k.name], k.range);

    Segment s;
    s.seconds = values["seconds"];
    s.force = Ramp::constant(values["force"]);
    s.beta = Ramp::constant(values["beta"]);
    s.finger = Ramp::constant(values["finger"]);
    if (name == "steady")
        s.speed = Ramp::constant(values["speed"]);
    else
    {
        s.acceleration = values["acceleration"];
        // From rest (GestureStart::speed is 0), so the bow reaches a * seconds; keep that in range too.
        const double end = values["acceleration"] * values["seconds"];
        if (!limits::speed.contains(end))
            throw GestureError(
                "acceleration", "acceleration x seconds within -5..5 m/s (the bow speed reached at the end)",
                formatNumber(values["acceleration"]) + " over " + formatNumber(values["seconds"]) +
                    " s (reaching " + formatNumber(end) + " m/s)");
    }
    GestureScript script;
    script.segments.push_back(s);
    return script;
}

std::string builtinGestureHelp(const std::string& indent)
{
    std::string text;
    for (const auto& b : builtins())
    {
        std::string keys;
        for (const auto& k : b.keys)
        {
            if (std::string(k.name) == "finger")
                continue;
            if (!keys.empty())
                keys += ',';
            keys += std::string(k.name) + "=" + formatNumber(k.defaultValue);
        }
        text += indent + b.name + ":" + keys + "\n" + indent + "    " + b.summary + "\n";
    }
    text += indent + "every key is optional (defaults shown); both also take finger=RATIO\n";
    text += indent + "(vibrating / open length, default 1 = open string)\n";
    return text;
}

} // namespace rosin::gesture
