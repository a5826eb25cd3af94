-- Host automation and read-back, headless (ardour7-lua, Dummy backend): a session with Rosin on a MIDI
-- track, then for every value of ROSIN_AUTOMATE an automation lane that holds it, played with the transport
-- rolling, and a snapshot of the session saved after it (the plugin's own state, which the test reads); each
-- lane ends on its default and is switched off before the next. Then the host bypasses the plugin and
-- enables it again, a snapshot after each. Then a factory program is loaded through
-- the host and what the host reads of every parameter is printed, and a last snapshot saved.
--
-- Printed, one line each (fields separated by "|"):
--   control|<key>|<label>|<lower>|<upper>|<toggled>|<integer step>|<range steps>|<host's value>
--   snapshot|<snapshot name>|<key>|<value>     (the first with neither: the state before any automation)
--   latency|<samples the host compensates for the plugin>
--   bypass|<snapshot name>|<1 when the host bypassed the plugin, else 0>
--   program|<label>|<snapshot name>
--   readback|<key>|<host's value>
--
-- Environment: ROSIN_SESSION_DIR, ROSIN_SESSION_NAME, ROSIN_SAMPLE_RATE, ROSIN_FORMAT (LV2 or VST3),
-- ROSIN_PLUGIN_ID, ROSIN_HOST_SCRIPTS (this folder), ROSIN_PROGRAM (a preset label), ROSIN_AUTOMATE:
-- "key=default:v1,v2,...;key=..." in the host's values (an LV2 property's own value, a VST3 parameter's
-- normalised one). A key is an LV2 property's name after the plugin URI, a VST3 parameter's title.
dofile(os.getenv("ROSIN_HOST_SCRIPTS") .. "/rosin_session.lua")

local dir, name = need("ROSIN_SESSION_DIR"), need("ROSIN_SESSION_NAME")
local rate = tonumber(need("ROSIN_SAMPLE_RATE"))
local format, id, program = need("ROSIN_FORMAT"), need("ROSIN_PLUGIN_ID"), need("ROSIN_PROGRAM")
local session, track, insert = rosin_session(dir, name, rate, format, id)
local automatable = track:nth_plugin(0):to_automatable()

-- The plugin's controls by key. An LV2 plugin's parameters are properties (patch:writable), which Ardour
-- automates under the property's URID; a VST3's are numbered from 0.
local function controls()
	local found, order = {}, {}
	local kind = format == "VST3" and ARDOUR.AutomationType.PluginAutomation
		or ARDOUR.AutomationType.PluginAutomation + 1 -- PluginPropertyAutomation
	local last = format == "VST3" and insert:plugin(0):parameter_count() - 1 or 4096
	for i = 0, last do
		local ac = automatable:automation_control(Evoral.Parameter(kind, 0, i), false)
		if not ac:isnil() then
			local key = format == "VST3" and ac:name() or ac:name():match(":([^:]+)$")
			found[key] = ac
			order[#order + 1] = key
		end
	end
	return found, order
end

local function roll(seconds)
	session:request_locate(0, false, ARDOUR.LocateTransportDisposition.MustStop,
		ARDOUR.TransportRequestSource.TRS_UI)
	ARDOUR.LuaAPI.usleep(100000)
	session:request_roll(ARDOUR.TransportRequestSource.TRS_UI)
	ARDOUR.LuaAPI.usleep(math.floor(seconds * 1e6))
	assert(session:transport_rolling(), "the transport does not roll")
	session:request_stop(false, false, ARDOUR.TransportRequestSource.TRS_UI)
	ARDOUR.LuaAPI.usleep(100000)
end

-- The lane holds one value over the first ten seconds, in Play mode.
local function hold(ac, value)
	local list = ac:alist()
	list:clear_list()
	list:add(Temporal.timepos_t(0), value, false, false)
	list:add(Temporal.timepos_t(10 * rate), value, false, false)
	ac:set_automation_state(ARDOUR.AutoState.Play)
	roll(0.2)
end

local found, order = controls()
for _, key in ipairs(order) do
	local ac, d = found[key], found[key]:desc()
	print(string.format("control|%s|%s|%.9g|%.9g|%s|%s|%d|%.9g", key, d.label, d.lower, d.upper,
		tostring(d.toggled), tostring(d.integer_step), d.rangesteps, ac:get_value()))
end

-- The plugin's state before any automation: what every later snapshot but one parameter must still hold.
session:save_state(name .. "-0", false, false, false, false, false)
print(string.format("snapshot|%s-0||", name))
-- The latency the host compensates for the plugin, as the plugin reports it.
print(string.format("latency|%d", insert:signal_latency()))
local taken = 0
for entry in need("ROSIN_AUTOMATE"):gmatch("[^;]+") do
	local key, default, values = entry:match("^(.-)=([^:]+):(.+)$")
	local ac = found[key]
	assert(ac ~= nil, "the host lists no parameter " .. key)
	for value in values:gmatch("[^,]+") do
		hold(ac, tonumber(value))
		taken = taken + 1
		local snapshot = string.format("%s-%d", name, taken)
		session:save_state(snapshot, false, false, false, false, false)
		print(string.format("snapshot|%s|%s|%s", snapshot, key, value))
	end
	hold(ac, tonumber(default))
	ac:set_automation_state(ARDOUR.AutoState.Off)
end

-- The host's own bypass: Ardour drives a VST3's bypass parameter (kIsBypass) and an LV2's lv2:enabled port.
for _, bypassed in ipairs({true, false}) do
	insert:enable(not bypassed)
	roll(0.2)
	taken = taken + 1
	local snapshot = string.format("%s-%d", name, taken)
	session:save_state(snapshot, false, false, false, false, false)
	print(string.format("bypass|%s|%d", snapshot, bypassed and 1 or 0))
end

local plugin = insert:plugin(0)
local preset = plugin:preset_by_label(program)
assert(preset ~= nil, "the " .. format .. " plugin offers no program " .. program)
assert(plugin:load_preset(preset), "the host could not load the program " .. program)
-- A VST3 host hears of the new values through the controller's restartComponent, on the message thread.
ARDOUR.LuaAPI.usleep(1500000)
local snapshot = name .. "-program"
session:save_state(snapshot, false, false, false, false, false)
print(string.format("program|%s|%s", plugin:last_preset().label, snapshot))
for _, key in ipairs(order) do
	print(string.format("readback|%s|%.9g", key, found[key]:get_value()))
end
close_session()
