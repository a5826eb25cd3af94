-- A new Ardour session with Rosin as the instrument of one MIDI track, connected to the master bus: shared
-- by the scripts that make sessions headless (ardour7-lua on the Dummy backend). Returns the session, the
-- track and the plugin insert.
-- An environment variable the script cannot go on without.
function need(name)
	local value = os.getenv(name)
	assert(value ~= nil and value ~= "", name .. " is not set")
	return value
end

function rosin_session(dir, name, rate, format, id)
	-- The Dummy backend is hidden from the backend list unless asked for.
	ARDOUR.config():set_hide_dummy_backend(false)
	local backend = AudioEngine:set_backend("None (Dummy)", "", "")
	assert(backend ~= nil and not backend:isnil(), "rosin_session: Ardour's Dummy backend is not available")
	backend:set_sample_rate(rate)

	local session = create_session(dir, name, rate)
	assert(session ~= nil, "rosin_session: cannot create the session in " .. dir)
	assert(session:nominal_sample_rate() == rate, "rosin_session: the session runs at "
		.. session:nominal_sample_rate() .. " Hz, not " .. rate)

	local ptype = format == "VST3" and ARDOUR.PluginType.VST3 or ARDOUR.PluginType.LV2
	local info = ARDOUR.LuaAPI.new_plugin_info(id, ptype)
	assert(not info:isnil(), "rosin_session: Ardour does not find the " .. format .. " plugin " .. id)

	local midi, audio = ARDOUR.DataType("midi"), ARDOUR.DataType("audio")
	local tracks = session:new_midi_track(ARDOUR.ChanCount(midi, 1), ARDOUR.ChanCount(audio, 2), true, info, nil,
		nil, 1, "Rosin", ARDOUR.PresentationInfo.max_order, ARDOUR.TrackMode.Normal, true, false)
	assert(tracks:size() == 1, "rosin_session: the MIDI track was not made")
	local track = tracks:front()
	-- The track's outputs to the master bus, made here: Ardour makes them on a thread of its own, which a
	-- session saved at once may not have waited for (its export is then silent).
	local master = session:master_out():input()
	for c = 0, 1 do
		local from, to = track:output():audio(c), master:audio(c):name()
		if not from:connected_to(to) then from:connect(to) end
		assert(from:connected_to(to), "rosin_session: cannot connect " .. from:name() .. " to " .. to)
	end
	local insert = track:nth_plugin(0):to_insert()
	assert(not insert:isnil(), "rosin_session: the track has no instrument")
	print("instrument: " .. insert:plugin(0):name() .. " (" .. format .. ")")
	return session, track, insert
end
