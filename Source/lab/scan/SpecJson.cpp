#include "lab/scan/SpecJson.h"

#include "core/config/ConfigError.h"
#include "core/physics/modal/SimdLevel.h"
#include "lab/scan/Variations.h"

namespace rosin::scan
{

namespace
{
using nlohmann::json;
constexpr const char* kFormat = "rosin-scan-spec/1";

json stringJson(const physics::StringParameters& s)
{
    return {{"name", s.name},
            {"tension", s.tension},
            {"massPerLength", s.massPerLength},
            {"length", s.length},
            {"bendingStiffness", s.bendingStiffness},
            {"lossF", s.lossF},
            {"lossB", s.lossB},
            {"lossA", s.lossA},
            {"stoppedLossF", s.stoppedLossF},
            {"torsionalWaveSpeed", s.torsionalWaveSpeed},
            {"torsionalQ", s.torsionalQ},
            {"torsionalImpedance", s.torsionalImpedance},
            {"source", s.source}};
}

json geometryJson(const physics::ContactGeometry& g)
{
    return {{"radius", g.radius},
            {"referenceForce", g.referenceForce},
            {"layerThickness", g.layerThickness},
            {"scaling", scalingName(g.scaling)}};
}

json materialJson(const physics::ThermalMaterial& m)
{
    return {{"conductivity", m.conductivity}, {"volumetricHeatCapacity", m.volumetricHeatCapacity}};
}

json contactJson(const physics::ContactParameters& c)
{
    return {{"rig", geometryJson(c.rig)},
            {"calibration", geometryJson(c.calibration)},
            {"layer", materialJson(c.materials.layer)},
            {"stationary", materialJson(c.materials.stationary)},
            {"moving", materialJson(c.materials.moving)},
            {"advectionWidthRatio", c.materials.advectionWidthRatio},
            {"ambientOffset", c.ambientOffset}};
}

// Reads one member with nlohmann's checks; any failure becomes a ConfigError naming the field.
class Reader
{
  public:
    Reader(const json& j, const std::string& file, std::string path)
        : j_(j), file_(file), path_(std::move(path))
    {
        if (!j_.is_object())
            throw config::ConfigError(file_, path_, "a JSON object");
    }
    template <typename T> T get(const char* key) const
    {
        const std::string field = path_.empty() ? key : path_ + "." + key;
        if (!j_.contains(key))
            throw config::ConfigError(file_, field, "a value", "nothing");
        try
        {
            return j_.at(key).get<T>();
        }
        catch (const json::exception&)
        {
            throw config::ConfigError(file_, field, "a value of the right type", j_.at(key).dump());
        }
    }
    bool has(const char* key) const { return j_.contains(key); }
    /// A ConfigError for `key` of this object.
    config::ConfigError error(const char* key, const std::string& expected) const
    {
        return config::ConfigError(file_, path_.empty() ? key : path_ + "." + key, expected);
    }
    Reader child(const char* key) const
    {
        if (!j_.contains(key))
            throw config::ConfigError(file_, path_.empty() ? key : path_ + "." + key, "an object", "nothing");
        return Reader(j_.at(key), file_, path_.empty() ? key : path_ + "." + key);
    }

  private:
    const json& j_;
    const std::string& file_;
    std::string path_;
};

physics::StringParameters readString(const Reader& r)
{
    physics::StringParameters s;
    s.name = r.get<std::string>("name");
    s.tension = r.get<double>("tension");
    s.massPerLength = r.get<double>("massPerLength");
    s.length = r.get<double>("length");
    s.bendingStiffness = r.get<double>("bendingStiffness");
    s.lossF = r.get<double>("lossF");
    s.lossB = r.get<double>("lossB");
    s.lossA = r.get<double>("lossA");
    s.stoppedLossF = r.get<double>("stoppedLossF");
    s.torsionalWaveSpeed = r.get<double>("torsionalWaveSpeed");
    s.torsionalQ = r.get<double>("torsionalQ");
    s.torsionalImpedance = r.get<double>("torsionalImpedance");
    s.source = r.get<std::string>("source");
    return s;
}

physics::ContactGeometry readGeometry(const Reader& r)
{
    physics::ContactGeometry g;
    g.radius = r.get<double>("radius");
    g.referenceForce = r.get<double>("referenceForce");
    g.layerThickness = r.get<double>("layerThickness");
    g.scaling = r.get<std::string>("scaling") == "hertz" ? physics::ContactScaling::Hertz
                                                         : physics::ContactScaling::Coulomb;
    return g;
}

physics::ThermalMaterial readMaterial(const Reader& r)
{
    return {r.get<double>("conductivity"), r.get<double>("volumetricHeatCapacity")};
}

// Files written before the two-sided heat balance have one "conductivity" and no solids: their rows came from
// another model, so they are named as such rather than read as if they were this one's.
physics::ContactParameters readContact(const Reader& r)
{
    if (!r.has("layer") && r.has("conductivity"))
        throw r.error("layer", "the two-sided heat balance's materials (this scan was written by a Rosin "
                               "with a one-sided heat balance: start it again in a new folder)");
    physics::ContactParameters c;
    c.rig = readGeometry(r.child("rig"));
    c.calibration = readGeometry(r.child("calibration"));
    c.materials.layer = readMaterial(r.child("layer"));
    c.materials.stationary = readMaterial(r.child("stationary"));
    c.materials.moving = readMaterial(r.child("moving"));
    c.materials.advectionWidthRatio = r.get<double>("advectionWidthRatio");
    c.ambientOffset = r.get<double>("ambientOffset");
    return c;
}

// "trialEnd"; files written before it had "endAfterTransient" (true: the window rule), and older ones
// nothing (whole trials). A resumed or merged scan keeps the rule its first rows were computed with.
GuettlerTrialEnd readTrialEnd(const Reader& r, const json& j, const std::string& file)
{
    if (!j.contains("trialEnd"))
        return j.contains("endAfterTransient") && r.get<bool>("endAfterTransient")
                   ? GuettlerTrialEnd::AfterWindow
                   : GuettlerTrialEnd::Whole;
    const auto name = r.get<std::string>("trialEnd");
    for (auto e : {GuettlerTrialEnd::Whole, GuettlerTrialEnd::AfterWindow, GuettlerTrialEnd::WhenDecided})
        if (name == trialEndName(e))
            return e;
    throw config::ConfigError(file, "trialEnd", "\"whole\", \"window\" or \"decided\"",
                              j.at("trialEnd").dump());
}
} // namespace

json specToJson(const ScanSpec& s)
{
    const ModelSpec& m = s.model;
    json j = {{"format", kFormat},
              {"kind", kindName(s.kind)},
              {"preset", m.preset},
              {"friction", m.friction},
              {"string", stringJson(m.string)},
              {"body", m.body},
              {"contact", contactJson(m.contact)},
              {"torsion", m.torsion},
              {"bendingStiffness", m.bendingStiffness},
              {"fingerDamping", m.fingerDamping},
              {"sampleRate", s.sampleRate},
              {"trialSeconds", s.trialSeconds},
              {"rampSeconds", s.rampSeconds},
              {"trialEnd", trialEndName(s.trialEnd)},
              {"betas", s.betas},
              {"forces", s.forces},
              {s.kind == ScanKind::Guettler ? "accelerations" : "bowSpeeds", s.second}};
    // Only when not the default, so that specs written before the option read back byte-identical.
    if (s.classification != Classification::State)
        j["classification"] = classificationName(s.classification);
    const physics::BowParameters& bow = m.bow;
    if (bow.width > 0.0 || bow.compliantHair)
        j["bow"] = {{"width", bow.width},
                    {"compliantHair", bow.compliantHair},
                    {"hairStiffness", bow.hairStiffness},
                    {"hairDamping", bow.hairDamping}};
    // The vector path of the process (ROSIN_SIMD): files are byte-identical however the work is split only on
    // one path, so a resume or a merge on another path is refused as another specification would be.
    j["kernels"] = physics::simdLevelName(physics::simdLevel());
    return j;
}

ScanSpec specFromJson(const json& j, const std::string& file)
{
    const Reader r(j, file, "");
    if (r.get<std::string>("format") != kFormat)
        throw config::ConfigError(file, "format", std::string("\"") + kFormat + "\"", j.at("format").dump());
    ScanSpec s;
    const std::string kind = r.get<std::string>("kind");
    if (kind != "schelleng" && kind != "guettler")
        throw config::ConfigError(file, "kind", "\"schelleng\" or \"guettler\"", j.at("kind").dump());
    s.kind = kind == "schelleng" ? ScanKind::Schelleng : ScanKind::Guettler;
    s.model.preset = r.get<std::string>("preset");
    s.model.friction = r.get<std::string>("friction");
    s.model.string = readString(r.child("string"));
    s.model.body = r.get<std::string>("body");
    s.model.contact = readContact(r.child("contact"));
    s.model.torsion = r.get<bool>("torsion");
    s.model.bendingStiffness = r.get<bool>("bendingStiffness");
    s.model.fingerDamping = r.get<bool>("fingerDamping");
    s.sampleRate = r.get<double>("sampleRate");
    s.trialSeconds = r.get<double>("trialSeconds");
    s.rampSeconds = r.get<double>("rampSeconds");
    s.trialEnd = readTrialEnd(r, j, file);
    if (r.has("bow"))
    {
        const Reader b = r.child("bow");
        s.model.bow = {b.get<double>("width"), b.get<bool>("compliantHair"), b.get<double>("hairStiffness"),
                       b.get<double>("hairDamping")};
    }
    if (r.has("classification"))
    {
        const auto c = r.get<std::string>("classification");
        if (c != "state" && c != "bridge-force")
            throw config::ConfigError(file, "classification", "\"state\" or \"bridge-force\"",
                                      j.at("classification").dump());
        s.classification = c == "bridge-force" ? Classification::BridgeForce : Classification::State;
    }
    s.betas = r.get<std::vector<double>>("betas");
    s.forces = r.get<std::vector<double>>("forces");
    s.second = r.get<std::vector<double>>(s.kind == ScanKind::Guettler ? "accelerations" : "bowSpeeds");
    if (s.betas.empty() || s.forces.empty() || s.second.empty())
        throw config::ConfigError(
            file, "betas/forces/" + std::string(s.kind == ScanKind::Guettler ? "accelerations" : "bowSpeeds"),
            "non-empty arrays of numbers");
    return s;
}

std::string specText(const ScanSpec& spec)
{
    return specToJson(spec).dump(2) + "\n";
}

ScanSpec specFromText(const std::string& text, const std::string& file)
{
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded())
        throw config::ConfigError(file, "", "a JSON scan specification (" + std::string(kFormat) + ")",
                                  "text that is not JSON");
    return specFromJson(j, file);
}

std::string describeSpecDifference(const std::string& ours, const std::string& theirs)
{
    const json a = json::parse(ours, nullptr, false), b = json::parse(theirs, nullptr, false);
    if (!a.is_object() || !b.is_object())
        return "the file is not a scan specification";
    auto shortText = [](const json* v)
    {
        std::string text = v != nullptr ? v->dump() : std::string("(absent)");
        return text.size() > 60 ? text.substr(0, 57) + "..." : text;
    };
    std::string text;
    json keys = a;
    keys.update(b);
    for (const auto& [key, unused] : keys.items())
    {
        const json* x = a.contains(key) ? &a.at(key) : nullptr;
        const json* y = b.contains(key) ? &b.at(key) : nullptr;
        if (x != nullptr && y != nullptr && *x == *y)
            continue;
        text += (text.empty() ? "" : "; ") + key + ": " + shortText(x) + " vs " + shortText(y);
    }
    return text.empty() ? "formatting only" : text;
}

} // namespace rosin::scan
