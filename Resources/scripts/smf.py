"""Standard MIDI files, as far as Rosin's scripts and host test need them: read every track into one list of
timed events, write one track back, and put the events of one tick in the order a host plays them.

An event is (tick, bytes); meta events keep their 0xFF prefix. Running status is expanded on reading.
"""
import struct


def _varlen(data, i):
    value = 0
    while True:
        byte = data[i]
        i += 1
        value = (value << 7) | (byte & 0x7F)
        if byte < 0x80:
            return value, i


def encode_varlen(n):
    out = [n & 0x7F]
    n >>= 7
    while n:
        out.insert(0, 0x80 | (n & 0x7F))
        n >>= 7
    return bytes(out)


def _data_length(status):
    return 1 if (status & 0xF0) in (0xC0, 0xD0) else 2


def _read_track(body):
    events, i, tick, running = [], 0, 0, 0
    while i < len(body):
        delta, i = _varlen(body, i)
        tick += delta
        status = body[i]
        if status == 0xFF:
            length, j = _varlen(body, i + 2)
            events.append((tick, bytes(body[i:j + length])))
            i = j + length
        elif status in (0xF0, 0xF7):
            length, j = _varlen(body, i + 1)
            events.append((tick, bytes(body[i:j + length])))
            i = j + length
        else:
            if status & 0x80:
                running, i = status, i + 1
            n = _data_length(running)
            events.append((tick, bytes([running]) + bytes(body[i:i + n])))
            i += n
    return events


def read(path):
    """(ticks per quarter note, events of all tracks merged in time order, stable within a tick)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"MThd":
        raise ValueError(f"{path}: not a standard MIDI file")
    _, tracks, division = struct.unpack(">HHH", data[8:14])
    if division & 0x8000:
        raise ValueError(f"{path}: SMPTE time division is not supported here")
    events, i = [], 8 + struct.unpack(">I", data[4:8])[0]
    for _ in range(tracks):
        length = struct.unpack(">I", data[i + 4:i + 8])[0]
        events += _read_track(data[i + 8:i + 8 + length])
        i += 8 + length
    events.sort(key=lambda e: e[0])  # stable: each track's order within a tick is kept
    return division, events


def write(path, division, events):
    """One track (format 0) holding `events`, in the order given."""
    track, now = bytearray(), 0
    for tick, message in events:
        if message[:2] == b"\xff\x2f":
            continue  # the end of track is written once, last
        track += encode_varlen(tick - now) + message
        now = tick
    track += b"\x00\xff\x2f\x00"
    with open(path, "wb") as f:
        f.write(b"MThd" + struct.pack(">IHHH", 6, 0, 1, division))
        f.write(b"MTrk" + struct.pack(">I", len(track)) + track)


def tempo_bpm(events):
    """The first tempo of the file (120 when it has none, as the standard says)."""
    for _, message in events:
        if message[:2] == b"\xff\x51":
            return 60e6 / int.from_bytes(message[3:6], "big")
    return 120.0


def last_tick(events):
    return max((tick for tick, _ in events), default=0)


def _host_rank(message):
    """Ardour keeps notes and controllers apart, and at one tick plays the controllers (bend, pressure and
    program too) before the notes, note-offs before note-ons: a file's own order inside a tick is lost there.
    Measured: a CC11 written after its note-on sounds the same in Ardour as one written before it."""
    if message[0] == 0xFF:
        return 0
    kind = message[0] & 0xF0
    if kind == 0x80 or (kind == 0x90 and message[2] == 0):
        return 2
    if kind == 0x90:
        return 3
    return 1


def in_host_order(events):
    """The same events with each tick's events in the order Ardour plays them."""
    return sorted(events, key=lambda e: (e[0], _host_rank(e[1])))


def delayed(events, ticks):
    """The channel and system events `ticks` later, the meta events (tempo, names) where they were. Ardour
    does not play a controller at the session's very start as written (measured: a CC11 at tick 0 sounds
    different there, one tick later it does not), so a file meant to sound the same there starts later."""
    return [(tick if message[0] == 0xFF else tick + ticks, message) for tick, message in events]


def for_host(events, division):
    """What the host test gives both renderers: Ardour's order, one beat late."""
    return in_host_order(delayed(events, division))
