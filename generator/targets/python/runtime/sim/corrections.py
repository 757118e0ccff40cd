"""RTCM3 corrections taken by the simulated device (docs/rtk-and-nmea.md, docs/simulator-world.md).

The device's parser reports each whole RTCM3 frame (0xD3, 10-bit length, CRC-24Q) between MIP
packets as an `Rtcm` event (codec.framing); `Simulator.feed` hands it here. What the device does
with it comes from the spec (`simulation.filters[].rtk.corrections`, carried in `_sim.FILTER`):

- a frame whose message type is not among `types` is counted in `unsupported` and ignored;
- while the SPARTN configuration (`spartn`: command, parameter) is enabled, every frame is
  counted in `blocked` and ignored (CV7 manual: enabling SPARTN blocks RTCM);
- a station position (`station`: 1005, 1006) is noted; an MSM observation (`observations`) with a
  station position known starts, or keeps alive, a run of corrections in the world
  (`World.rtk_corrections`, the same intervals `--rtk-corrections` gives): the run lasts until
  `max_age` seconds of simulated time after the newest observation, so the receivers go to RTK
  float and RTK fixed with the world's timing while observations keep coming and fall back when
  they stop. A new run after one aged out needs a station position again.
"""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Tuple


class Corrections:
    """The RTCM3 intake of one simulated device (`profile`: its `_sim.FILTER` entry)."""

    def __init__(self, profile: Dict[str, Any], world: Any) -> None:
        self.spec: Optional[Dict[str, Any]] = (profile.get("rtk") or {}).get("corrections")
        self.world = world
        self.taken: Dict[int, int] = {}  # supported message type -> frames taken
        self.unsupported: Dict[int, int] = {}  # unsupported message type -> frames ignored
        self.blocked = 0  # frames ignored while SPARTN is enabled
        self.station_at: Optional[float] = None  # simulated time of the newest station position
        self.observed_at: Optional[float] = None  # ... of the newest observation taken
        self._run: Optional[int] = None  # index of the current run in world.rtk_corrections

    def take(self, message_type: int, t: float, spartn: bool = False) -> str:
        """A frame of `message_type` arriving at simulated time t: "unsupported", "blocked",
        "station", "observation" (used: corrections flow) or "held" (a supported type that
        starts nothing: an observation without a station position, 1007, 1033, 1230)."""
        spec = self.spec
        if spec is None or message_type not in spec["types"]:
            self.unsupported[message_type] = self.unsupported.get(message_type, 0) + 1
            return "unsupported"
        if spartn:
            self.blocked += 1
            return "blocked"
        self.taken[message_type] = self.taken.get(message_type, 0) + 1
        if message_type in spec["station"]:
            self.station_at = t
            return "station"
        if message_type not in spec["observations"]:
            return "held"
        runs: List[Tuple[float, float]] = self.world.rtk_corrections
        run = runs[self._run] if self._run is not None else None
        end = t + spec["max_age"]
        if run is not None and t < run[1]:
            runs[self._run] = (run[0], max(run[1], end))  # type: ignore[index]
        elif self.station_at is not None and (run is None or self.station_at >= run[1]):
            runs.append((t, end))
            self._run = len(runs) - 1
        else:
            return "held"
        self.observed_at = t
        return "observation"

    def age(self, t: float) -> Optional[float]:
        """Seconds since the newest observation taken (None: none yet)."""
        return None if self.observed_at is None else max(0.0, t - self.observed_at)

    def flowing(self, t: float) -> bool:
        """Whether the corrections taken are fresh at t (a run in progress)."""
        return self._run is not None and self.world.rtk_corrections[self._run][1] > t


def feed(sim: Any, frame: Any, now: float) -> str:
    """An `Rtcm` event that reached `sim` (a Simulator) at real time `now`."""
    spec = sim.corrections.spec
    spartn = False
    if spec is not None and spec.get("spartn"):
        command, param = spec["spartn"]
        spartn = any(sim._setting_on(cls, param) for cls in sim._named(command))
    sim._world_at = None  # the world's RTK state may change
    taken: str = sim.corrections.take(frame.message_type, sim.sim_time(now), spartn)
    return taken
