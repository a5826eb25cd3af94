-- Makes an Ardour session headless (ardour7-lua, Dummy backend): one MIDI track whose instrument is Rosin,
-- connected to the master bus, optionally on one of the plugin's factory programs chosen as a host preset,
-- and saves it. The region and the session range are added to the saved file afterwards
-- (ardour_session.py): Ardour 7.3's Lua has no headless MIDI import.
--
-- Environment: ROSIN_SESSION_DIR, ROSIN_SESSION_NAME, ROSIN_SAMPLE_RATE, ROSIN_FORMAT (LV2 or VST3),
-- ROSIN_PLUGIN_ID (the LV2 URI or the VST3 class id), ROSIN_PROGRAM (a preset label, or empty),
-- ROSIN_HOST_SCRIPTS (this folder).
dofile(os.getenv("ROSIN_HOST_SCRIPTS") .. "/rosin_session.lua")

local dir, name = need("ROSIN_SESSION_DIR"), need("ROSIN_SESSION_NAME")
local rate = tonumber(need("ROSIN_SAMPLE_RATE"))
local format, id = need("ROSIN_FORMAT"), need("ROSIN_PLUGIN_ID")
local program = os.getenv("ROSIN_PROGRAM") or ""

local session, track, insert = rosin_session(dir, name, rate, format, id)
local plugin = insert:plugin(0)

-- A factory program as the host offers it: an LV2 preset, a VST3 program (listed once instantiated).
if program ~= "" then
	local preset = plugin:preset_by_label(program)
	assert(preset ~= nil, "make_session.lua: the " .. format .. " plugin offers no program " .. program)
	assert(plugin:load_preset(preset), "make_session.lua: the host could not load the program " .. program)
	print("program: " .. plugin:last_preset().label)
end

session:save_state("", false, false, false, false, false)
close_session()
