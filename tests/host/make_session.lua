-- Makes an Ardour session headless (ardour7-lua, Dummy backend): one MIDI track whose instrument is Rosin,
-- connected to the master bus, optionally on one of the plugin's factory programs chosen as a host preset,
-- and saves it. The region and the session range are added to the saved file afterwards
-- (ardour_session.py): Ardour 7.3's Lua has no headless MIDI import.
--
-- Environment: ROSIN_SESSION_DIR, ROSIN_SESSION_NAME, ROSIN_SAMPLE_RATE, ROSIN_FORMAT (LV2 or VST3),
-- ROSIN_PLUGIN_ID (the LV2 URI or the VST3 class id), ROSIN_PROGRAM (a preset label, or empty).
local function need(name)
	local value = os.getenv(name)
	assert(value ~= nil and value ~= "", "make_session.lua: " .. name .. " is not set")
	return value
end

local dir, name = need("ROSIN_SESSION_DIR"), need("ROSIN_SESSION_NAME")
local rate = tonumber(need("ROSIN_SAMPLE_RATE"))
local format, id = need("ROSIN_FORMAT"), need("ROSIN_PLUGIN_ID")
local program = os.getenv("ROSIN_PROGRAM") or ""

-- The Dummy backend is hidden from the backend list unless asked for.
ARDOUR.config():set_hide_dummy_backend(false)
local backend = AudioEngine:set_backend("None (Dummy)", "", "")
assert(backend ~= nil and not backend:isnil(), "make_session.lua: Ardour's Dummy backend is not available")
backend:set_sample_rate(rate)

local session = create_session(dir, name, rate)
assert(session ~= nil, "make_session.lua: cannot create the session in " .. dir)
assert(session:nominal_sample_rate() == rate, "make_session.lua: the session runs at "
	.. session:nominal_sample_rate() .. " Hz, not " .. rate)

local ptype = format == "VST3" and ARDOUR.PluginType.VST3 or ARDOUR.PluginType.LV2
local info = ARDOUR.LuaAPI.new_plugin_info(id, ptype)
assert(not info:isnil(), "make_session.lua: Ardour does not find the " .. format .. " plugin " .. id)

local midi, audio = ARDOUR.DataType("midi"), ARDOUR.DataType("audio")
local tracks = session:new_midi_track(ARDOUR.ChanCount(midi, 1), ARDOUR.ChanCount(audio, 2), true, info, nil,
	nil, 1, "Rosin", ARDOUR.PresentationInfo.max_order, ARDOUR.TrackMode.Normal, true, false)
assert(tracks:size() == 1, "make_session.lua: the MIDI track was not made")
local track = tracks:front()
-- The track's outputs to the master bus, made here: Ardour makes them on a thread of its own, which a
-- session saved at once may not have waited for (its export is then silent).
local master = session:master_out():input()
for c = 0, 1 do
	local from, to = track:output():audio(c), master:audio(c):name()
	if not from:connected_to(to) then from:connect(to) end
	assert(from:connected_to(to), "make_session.lua: cannot connect " .. from:name() .. " to " .. to)
end
local insert = track:nth_plugin(0):to_insert()
assert(not insert:isnil(), "make_session.lua: the track has no instrument")
local plugin = insert:plugin(0)
print("instrument: " .. plugin:name() .. " (" .. format .. ")")

-- A factory program as the host offers it: an LV2 preset, a VST3 program (listed once instantiated).
if program ~= "" then
	local preset = plugin:preset_by_label(program)
	assert(preset ~= nil, "make_session.lua: the " .. format .. " plugin offers no program " .. program)
	assert(plugin:load_preset(preset), "make_session.lua: the host could not load the program " .. program)
	print("program: " .. plugin:last_preset().label)
end

session:save_state("", false, false, false, false, false)
close_session()
