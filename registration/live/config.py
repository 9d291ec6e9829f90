"""The live service's settings (:class:`ServeConfig`), from the command line and optionally a TOML
file (``--config``): the file's keys are the long options without their dashes, with ``_`` for
``-`` (``cat063_period_s = 10``; ``asterix = ["udp://239.1.1.1:8600"]``); an option given on the
command line wins over the file. Addresses are ``udp://HOST:PORT`` (or ``tcp://`` where said), HOST
an IPv4 address or ``localhost``; names are not looked up."""

from __future__ import annotations

import datetime as dt
import ipaddress
import tomllib
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any, Mapping

__all__ = ["Endpoint", "ServeConfig", "parse_host_port", "read_config_file"]


@dataclass(frozen=True)
class Endpoint:
    """``scheme://host:port``; ``host`` an IPv4 address text."""

    scheme: str
    host: str
    port: int

    @property
    def multicast(self) -> bool:
        return ipaddress.IPv4Address(self.host).is_multicast

    def __str__(self) -> str:
        return f"{self.scheme}://{self.host}:{self.port}"

    @staticmethod
    def parse(text: str, what: str, schemes: tuple[str, ...] = ("udp",)) -> "Endpoint":
        """``udp://HOST:PORT`` -> Endpoint; ValueError naming ``what`` (the option) otherwise."""
        scheme, sep, rest = str(text).partition("://")
        if not sep or scheme not in schemes:
            raise ValueError(f"{what}: {text!r} is not {' or '.join(s + '://HOST:PORT' for s in schemes)}")
        host, port = parse_host_port(rest, what)
        return Endpoint(scheme, host, port)


def parse_host_port(text: str, what: str) -> tuple[str, int]:
    """``HOST:PORT`` -> (IPv4 text, port); ``localhost`` is 127.0.0.1. ValueError naming ``what``."""
    host, sep, port = str(text).rpartition(":")
    host = "127.0.0.1" if host == "localhost" else host
    try:
        ipaddress.IPv4Address(host)
        number = int(port)
    except ValueError:
        raise ValueError(
            f"{what}: {text!r} is not HOST:PORT with an IPv4 address and a port number"
        ) from None
    if not sep or not 0 <= number <= 65535:
        raise ValueError(f"{what}: {text!r}: the port must be 0 to 65535")
    return host, number


@dataclass(frozen=True, kw_only=True)
class ServeConfig:
    """Settings of ``registration serve`` (docs/howto/serve.md); times in s of data unless said."""

    sites: Path | None = None
    asterix: tuple[Endpoint, ...] = ()
    nmea: Endpoint | None = None  # udp:// listened to, tcp:// connected to (a multiplexer's server)
    platform: str | None = None  # the ship of the NMEA stream
    sensors: Path | None = None  # its sensors file (optional talker column)
    interface: str = "0.0.0.0"
    http: tuple[str, int] = ("127.0.0.1", 8063)
    cat063: Endpoint | None = None
    cat063_period_s: float = 10.0  # wall-clock seconds between CAT063 messages
    sac_sic: tuple[int, int] = (25, 200)  # the service's own data source identifier
    corrected: Endpoint | None = None
    state: Path | None = None
    checkpoint_s: float = 60.0  # wall-clock seconds between checkpoints
    window_s: float = 20.0  # the filter's epochs (target windows)
    alarm_window_s: float = 60.0
    cat021_edition: str | None = None
    date: dt.date | None = None
    tick_s: float = 0.2  # wall-clock seconds between processing rounds
    extra: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for name in ("cat063_period_s", "checkpoint_s", "window_s", "alarm_window_s", "tick_s"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and v > 0):
                raise ValueError(f"--{name.replace('_', '-')}: expected a time > 0 s, got {v!r}")
        if self.alarm_window_s < self.window_s:
            raise ValueError(
                f"--alarm-window-s {self.alarm_window_s:g}: shorter than one epoch "
                f"(--window-s {self.window_s:g})"
            )
        if not self.asterix and self.nmea is None:
            raise ValueError(
                "--asterix, --nmea: give at least one input (--asterix udp://HOST:PORT, --nmea udp:// or tcp://)"
            )
        if self.asterix and self.sites is None:
            raise ValueError("--sites: give the SITES.csv of the radars of --asterix")
        if self.nmea is not None and (self.platform is None or self.sensors is None):
            raise ValueError("--nmea: give the ship's --platform NAME and its --sensors SENSORS.csv")
        sac, sic = self.sac_sic
        if not (0 <= sac <= 255 and 0 <= sic <= 255):
            raise ValueError(f"--sac-sic: {sac}/{sic}: SAC and SIC are 0 to 255")


def read_config_file(path: Path) -> dict:
    """The TOML file's settings as option values (keys with ``_``); ValueError naming the file and
    the unknown keys."""
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: not a TOML file ({exc})") from None
    known = {f.name for f in fields(ServeConfig)} - {"extra"}
    unknown = sorted(set(data) - known)
    if unknown:
        raise ValueError(f"{path}: unknown setting(s) {unknown}; known: {sorted(known)}")
    return data
