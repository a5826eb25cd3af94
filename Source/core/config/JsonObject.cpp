#include "core/config/JsonObject.h"

#include <algorithm>

namespace rosin::config
{

std::string describeJson(const nlohmann::json& value)
{
    switch (value.type())
    {
    case nlohmann::json::value_t::null:
        return "null";
    case nlohmann::json::value_t::object:
        return "an object";
    case nlohmann::json::value_t::array:
        return "an array";
    case nlohmann::json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    case nlohmann::json::value_t::string:
    {
        std::string text = value.get<std::string>();
        if (text.size() > 60)
        {
            // Cut at a character boundary: a cut inside a UTF-8 sequence made dump() throw (found by
            // fuzzing).
            std::size_t cut = 57;
            while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
                --cut;
            text = text.substr(0, cut) + "...";
        }
        return nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    default:
        return value.is_number() ? physics::formatNumber(value.get<double>()) : value.dump();
    }
}

std::string oneOfText(const std::vector<std::string>& allowed)
{
    std::string text = "one of ";
    for (std::size_t i = 0; i < allowed.size(); ++i)
        text += (i ? ", " : "") + allowed[i];
    return text;
}

JsonObject::JsonObject(const nlohmann::json& value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(std::move(path))
{
    if (!value_.is_object())
        throw ConfigError(file_, path_, "a JSON object", describeJson(value_));
}

void JsonObject::fail(const std::string& key, const std::string& expected, const std::string& got) const
{
    throw ConfigError(file_, path(key), expected, got);
}

double JsonObject::number(const std::string& key, const physics::Range& range) const
{
    if (!has(key))
        fail(key, range.describe(), "nothing (the field is required)");
    return *optionalNumber(key, range);
}

std::optional<double> JsonObject::optionalNumber(const std::string& key, const physics::Range& range) const
{
    if (!has(key))
        return std::nullopt;
    const auto& v = at(key);
    if (!v.is_number() || !range.contains(v.get<double>()))
        fail(key, range.describe(), describeJson(v));
    return v.get<double>();
}

std::optional<bool> JsonObject::optionalBool(const std::string& key) const
{
    if (!has(key))
        return std::nullopt;
    const auto& v = at(key);
    if (!v.is_boolean())
        fail(key, "true or false", describeJson(v));
    return v.get<bool>();
}

std::optional<std::string> JsonObject::optionalString(const std::string& key) const
{
    if (!has(key))
        return std::nullopt;
    const auto& v = at(key);
    if (!v.is_string())
        fail(key, "a string", describeJson(v));
    return v.get<std::string>();
}

std::optional<std::string> JsonObject::optionalOneOf(const std::string& key,
                                                     const std::vector<std::string>& allowed) const
{
    if (!has(key))
        return std::nullopt;
    const auto& v = at(key);
    if (!v.is_string() || std::find(allowed.begin(), allowed.end(), v.get<std::string>()) == allowed.end())
        fail(key, oneOfText(allowed), describeJson(v));
    return v.get<std::string>();
}

JsonObject JsonObject::object(const std::string& key) const
{
    if (!has(key))
        fail(key, "an object", "nothing (the field is required)");
    return JsonObject(at(key), file_, path(key));
}

void JsonObject::allowOnly(std::initializer_list<const char*> known) const
{
    for (const auto& item : value_.items())
    {
        const std::string& key = item.key();
        const bool ok = std::any_of(known.begin(), known.end(), [&](const char* k) { return key == k; });
        if (!ok)
        {
            std::string list;
            for (const char* k : known)
                list += (list.empty() ? "" : ", ") + std::string(k);
            fail(key, "one of the known fields " + list, "an unknown field");
        }
    }
}

} // namespace rosin::config
