#include "core/config/PresetLoader.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/config/InstalledData.h"
#include "core/config/JsonFile.h"
#include "core/config/JsonObject.h"
#include "core/config/VoiceSetup.h"
#include "core/gesture/GestureLimits.h"
#include "core/physics/thermal/RosinMaterial.h"

#ifndef ROSIN_PRESET_DIR
#define ROSIN_PRESET_DIR "presets"
#endif

namespace rosin::config
{

namespace fs = std::filesystem;
using physics::Range;

namespace
{
// Generous physical bounds: they catch unit slips (mm for m, g for kg) without judging the instrument.
constexpr Range kTension{1.0, 5000.0, "N"};
constexpr Range kMassPerLength{1e-5, 0.1, "kg/m"};
constexpr Range kLength{0.05, 3.0, "m"};
constexpr Range kBendingStiffness{0.0, 0.1, "N m^2"};
constexpr Range kLossCoefficient{0.0, 10000.0, "as printed in [Galluzzo2017] Table 1"};
constexpr Range kLossA{0.0, 1000.0, "1/s"};
constexpr Range kTorsionalWaveSpeed{1.0, 100000.0, "m/s"};
constexpr Range kTorsionalQ{1.0, 10000.0, ""};
constexpr Range kTorsionalImpedance{1e-3, 1000.0, "kg/s"};
constexpr Range kContactRadius{1e-6, 0.01, "m"};
constexpr Range kReferenceForce{1e-3, 100.0, "N"};
constexpr Range kLayerThickness{1e-9, 1e-3, "m"};
constexpr Range kAmbientOffset{-50.0, 100.0, "K"};
constexpr Range kOutputLevel{-60.0, 12.0, "dB"}; // the plugin's outputLevel parameter
constexpr Range kGainFrequency{20.0, 20000.0, "Hz"};
constexpr Range kGain{-30.0, 30.0, "dB"};
constexpr Range kRigFrequency{1.0, 10000.0, "Hz"};
constexpr Range kRigQ{0.6, 1e5, ""};
constexpr Range kRigMass{1e-5, 100.0, "kg"};

physics::StringParameters catalogueString(const JsonObject& owner, const std::string& key,
                                          const std::string& name)
{
    const auto names = physics::stringCatalogueNames();
    if (std::find(names.begin(), names.end(), name) == names.end())
        owner.fail(key, "a catalogue string, " + oneOfText(names), nlohmann::json(name).dump());
    return physics::stringFromCatalogue(name);
}

physics::StringParameters parseInlineString(const JsonObject& s)
{
    s.allowOnly({"base", "name", "source", "tension", "massPerLength", "length", "bendingStiffness", "lossF",
                 "lossB", "lossA", "stoppedLossF", "torsionalWaveSpeed", "torsionalQ", "torsionalImpedance"});
    physics::StringParameters p;
    if (const auto base = s.optionalString("base"))
        p = catalogueString(s, "base", *base);
    else
    {
        // Without a base the defining quantities must be given; the rest default to the cello D3's values.
        for (const char* key : {"tension", "massPerLength", "length"})
            if (!s.has(key))
                s.fail(key, "a number (required when \"base\" is absent)", "nothing");
        p.name = "custom";
        p.source = "preset";
    }
    p.name = s.optionalString("name").value_or(p.name);
    p.source = s.optionalString("source").value_or(p.source);
    p.tension = s.optionalNumber("tension", kTension).value_or(p.tension);
    p.massPerLength = s.optionalNumber("massPerLength", kMassPerLength).value_or(p.massPerLength);
    p.length = s.optionalNumber("length", kLength).value_or(p.length);
    p.bendingStiffness = s.optionalNumber("bendingStiffness", kBendingStiffness).value_or(p.bendingStiffness);
    p.lossF = s.optionalNumber("lossF", kLossCoefficient).value_or(p.lossF);
    p.lossB = s.optionalNumber("lossB", kLossCoefficient).value_or(p.lossB);
    p.lossA = s.optionalNumber("lossA", kLossA).value_or(p.lossA);
    p.stoppedLossF = s.optionalNumber("stoppedLossF", kLossCoefficient).value_or(p.stoppedLossF);
    p.torsionalWaveSpeed =
        s.optionalNumber("torsionalWaveSpeed", kTorsionalWaveSpeed).value_or(p.torsionalWaveSpeed);
    p.torsionalQ = s.optionalNumber("torsionalQ", kTorsionalQ).value_or(p.torsionalQ);
    p.torsionalImpedance =
        s.optionalNumber("torsionalImpedance", kTorsionalImpedance).value_or(p.torsionalImpedance);
    return p;
}

void parseContact(const JsonObject& root, Preset& preset)
{
    if (!root.has("contact"))
        return;
    if (root.at("contact").is_string())
    {
        preset.contact = *root.optionalOneOf("contact", contactNames());
        return;
    }
    if (!root.at("contact").is_object())
        root.fail("contact", "a contact name (" + oneOfText(contactNames()) + ") or an object",
                  describeJson(root.at("contact")));
    const JsonObject c = root.object("contact");
    c.allowOnly({"base", "radius", "referenceForce", "layerThickness", "scaling"});
    preset.contact = c.optionalOneOf("base", contactNames()).value_or(preset.contact);
    auto& o = preset.contactOverrides;
    o.radius = c.optionalNumber("radius", kContactRadius);
    o.referenceForce = c.optionalNumber("referenceForce", kReferenceForce);
    o.layerThickness = c.optionalNumber("layerThickness", kLayerThickness);
    if (const auto scaling = c.optionalOneOf("scaling", {"coulomb", "hertz"}))
        o.scaling = *scaling == "hertz" ? physics::ContactScaling::Hertz : physics::ContactScaling::Coulomb;
}

// "bow": {"width": m, "hair": "rigid" | "horsehair", "hairStiffness": N/m, "hairDamping": kg/s, "slipNoise":
// relative rms | "ribbon"}; the two hair numbers change the horsehair values (and imply compliant hair).
// A number, or "ribbon": the estimate from the hairs on the string (physics::ribbonSlipNoise).
double slipNoiseOf(const JsonObject& b)
{
    if (b.has("slipNoise") && b.at("slipNoise").is_string())
    {
        b.optionalOneOf("slipNoise", {"ribbon"});
        return physics::ribbonSlipNoise();
    }
    return b.optionalNumber("slipNoise", physics::limits::slipNoise).value_or(0.0);
}

void parseBow(const JsonObject& root, Preset& preset)
{
    if (!root.has("bow"))
        return;
    const JsonObject b = root.object("bow");
    b.allowOnly({"width", "hair", "hairStiffness", "hairDamping", "slipNoise"});
    const double width = b.optionalNumber("width", physics::limits::bowWidth).value_or(0.0);
    const auto hair = b.optionalOneOf("hair", {"rigid", "horsehair"});
    const auto stiffness = b.optionalNumber("hairStiffness", physics::limits::hairStiffness);
    const auto damping = b.optionalNumber("hairDamping", physics::limits::hairDamping);
    if (hair == std::optional<std::string>("rigid") && (stiffness || damping))
        b.fail("hair", "\"horsehair\" (or no \"hair\") when hairStiffness or hairDamping is given",
               "\"rigid\"");
    physics::BowParameters bow = physics::horsehairBow(width);
    bow.compliantHair = hair == std::optional<std::string>("horsehair") || stiffness || damping;
    bow.hairStiffness = stiffness.value_or(bow.hairStiffness);
    bow.hairDamping = damping.value_or(bow.hairDamping);
    if (!bow.compliantHair)
        bow = physics::BowParameters{.width = width};
    bow.slipNoise = slipNoiseOf(b);
    preset.bow = bow;
}

// "rig": {"type": "oscillator", "frequency", "qualityFactor", "modalMass", "normalForce", "rodSpeed"}.
void parseRig(const JsonObject& root, Preset& preset)
{
    if (!root.has("rig"))
        return;
    const JsonObject r = root.object("rig");
    r.allowOnly({"type", "frequency", "qualityFactor", "modalMass", "normalForce", "rodSpeed"});
    if (!r.has("type"))
        r.fail("type", "\"oscillator\" (the only rig so far)", "nothing");
    r.optionalOneOf("type", {"oscillator"});
    RigPreset rig;
    auto& o = rig.oscillator;
    o.frequency = r.optionalNumber("frequency", kRigFrequency).value_or(o.frequency);
    o.qualityFactor = r.optionalNumber("qualityFactor", kRigQ).value_or(o.qualityFactor);
    o.modalMass = r.optionalNumber("modalMass", kRigMass).value_or(o.modalMass);
    rig.normalForce = r.optionalNumber("normalForce", gesture::limits::force).value_or(rig.normalForce);
    rig.rodSpeed = r.optionalNumber("rodSpeed", gesture::limits::speed).value_or(rig.rodSpeed);
    preset.rig = rig;
}
} // namespace

std::string presetDirectory()
{
    if (const char* env = std::getenv("ROSIN_PRESET_DIR"); env != nullptr && *env != '\0')
        return env;
    std::error_code ec;
    for (const auto& folder : installedDataFolders("presets"))
        if (fs::is_directory(folder, ec))
            return folder;
    return ROSIN_PRESET_DIR; // the source tree: tests and tools run from other folders of the build
}

std::vector<std::string> presetNames()
{
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(presetDirectory(), ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".json")
            names.push_back(it->path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string resolvePresetPath(const std::string& nameOrPath)
{
    const bool isPath =
        nameOrPath.find('/') != std::string::npos || (nameOrPath.size() > 5 && nameOrPath.ends_with(".json"));
    if (isPath)
        return nameOrPath;
    return (fs::path(presetDirectory()) / (nameOrPath + ".json")).string();
}

Preset loadPreset(const std::string& nameOrPath)
{
    if (nameOrPath.empty())
        throw ConfigError("--preset", "", "a preset name or a .json file", "an empty string");
    const std::string path = resolvePresetPath(nameOrPath);
    std::error_code ec;
    if (path != nameOrPath && !fs::exists(path, ec))
    {
        std::string known;
        for (const auto& n : presetNames())
            known += (known.empty() ? "" : ", ") + n;
        throw ConfigError(path, "",
                          "a preset name (one of " + (known.empty() ? "none found" : known) +
                              ") or a path to a .json file",
                          "\"" + nameOrPath + "\", which has no file");
    }
    return parsePreset(readJsonFile(path), path, fs::path(path).stem().string());
}

namespace
{
/// "radiationGains": [{"hz": 125, "db": 2.5}, ...], frequencies strictly ascending.
void parseRadiationGains(const JsonObject& r, Preset& p)
{
    if (!r.has("radiationGains"))
        return;
    const auto& points = r.at("radiationGains");
    if (!points.is_array() || points.empty())
        r.fail("radiationGains", "a non-empty array of {\"hz\": ..., \"db\": ...} points",
               describeJson(points));
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const std::string path = r.path("radiationGains") + "[" + std::to_string(i) + "]";
        const JsonObject point(points[i], r.file(), path);
        point.allowOnly({"hz", "db"});
        physics::RadiationGainPoint g{point.number("hz", kGainFrequency), point.number("db", kGain)};
        if (!p.radiationGains.empty() && !(g.frequencyHz > p.radiationGains.back().frequencyHz))
            point.fail("hz",
                       "a frequency above the previous point's " +
                           std::to_string(p.radiationGains.back().frequencyHz) + " Hz",
                       describeJson(points[i].at("hz")));
        p.radiationGains.push_back(g);
    }
}

void parsePlayer(const JsonObject& r, Preset& p)
{
    if (!r.has("player"))
        return;
    const JsonObject o = r.object("player");
    o.allowOnly({"mapping", "dynamics", "bowPressure", "vibratoDepth", "vibratoRate", "vibratoDelay",
                 "slideTime", "tremoloRate", "articulation"});
    namespace l = gesture::limits;
    PlayerPreset player;
    player.mapping = o.optionalOneOf("mapping", {"lab", "musical"}).value_or(player.mapping);
    player.dynamics = o.optionalNumber("dynamics", l::dynamics);
    player.bowPressure = o.optionalNumber("bowPressure", l::bowPressure);
    player.vibratoDepth = o.optionalNumber("vibratoDepth", l::vibratoDepth);
    player.vibratoRate = o.optionalNumber("vibratoRate", l::vibratoRate);
    player.vibratoDelay = o.optionalNumber("vibratoDelay", l::vibratoDelay);
    player.slideTime = o.optionalNumber("slideTime", l::slideTime);
    player.tremoloRate = o.optionalNumber("tremoloRate", l::tremoloRate);
    player.articulation = o.optionalOneOf("articulation", {"arco", "pizzicato"});
    p.player = player;
}
} // namespace

Preset parsePreset(const nlohmann::json& root, const std::string& file, const std::string& defaultName)
{
    requireFormat(root, file, "rosin-preset/1");
    const JsonObject r(root, file, "");
    r.allowOnly({"format", "name", "description", "string", "body", "friction", "contact", "torsion",
                 "bendingStiffness", "ambientOffset", "beta", "outputLevel", "bodyResponse", "rig", "player",
                 "radiationGains", "bow", "rosin"});

    Preset p = defaultPreset();
    p.source = file;
    p.name = r.optionalString("name").value_or(defaultName);
    p.description = r.optionalString("description").value_or("");
    if (r.has("string"))
    {
        const auto& s = r.at("string");
        if (s.is_string())
            p.string = catalogueString(r, "string", s.get<std::string>());
        else if (s.is_object())
            p.string = parseInlineString(r.object("string"));
        else
            r.fail("string", "a catalogue name or a string object", describeJson(s));
    }
    p.body = r.optionalOneOf("body", bodyNames()).value_or(p.body);
    p.friction = r.optionalOneOf("friction", frictionNames()).value_or(p.friction);
    parseContact(r, p);
    p.rosin = r.optionalOneOf("rosin", physics::rosinMaterialNames()).value_or(p.rosin);
    parseBow(r, p);
    p.torsion = r.optionalBool("torsion").value_or(p.torsion);
    p.bendingStiffness = r.optionalBool("bendingStiffness").value_or(p.bendingStiffness);
    p.ambientOffset = r.optionalNumber("ambientOffset", kAmbientOffset).value_or(p.ambientOffset);
    p.beta = r.optionalNumber("beta", gesture::limits::beta).value_or(p.beta);
    p.outputLevel = r.optionalNumber("outputLevel", kOutputLevel);
    if (const auto response = r.optionalString("bodyResponse"))
    {
        const auto path = std::filesystem::path(file).parent_path() / *response;
        if (!std::filesystem::is_regular_file(path))
            r.fail("bodyResponse", "an existing audio file (relative to the preset's folder)",
                   "\"" + *response + "\" (" + path.string() + " does not exist)");
        p.bodyResponse = std::filesystem::absolute(path).lexically_normal().string();
    }
    parseRig(r, p);
    parsePlayer(r, p);
    parseRadiationGains(r, p);
    return p;
}

} // namespace rosin::config
