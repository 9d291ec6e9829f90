"""``registration serve``: the live service between the radars and the tracker
(:mod:`registration.live.service`; docs/howto/serve.md)."""

from __future__ import annotations

import argparse
import datetime as dt
import sys
from pathlib import Path

__all__ = ["HELP", "add_arguments", "run", "config_from_args"]

HELP = (
    "live registration: listen to ASTERIX over UDP and a ship's NMEA (UDP or TCP), estimate the radars' "
    "biases as the plots stream, serve a page and a JSON API, send CAT063 and corrected plots"
)

#: option dest -> default, where the TOML file may give the value instead
_DEFAULTS = {
    "interface": "0.0.0.0",
    "http": "127.0.0.1:8063",
    "cat063_period_s": 10.0,
    "sac_sic": "25/200",
    "checkpoint_s": 60.0,
    "window_s": 20.0,
    "alarm_window_s": 60.0,
}


#: option -> (metavar, help)
_OPTIONS = {
    "--config": (
        "FILE.toml",
        "settings in a TOML file (keys: the long options with _ for -); the command line wins over it",
    ),
    "--sites": (
        "SITES.csv",
        "the radars: sensor, sac, sic, lat_deg, lon_deg, alt_m, sigma_range_m, sigma_bearing_deg and "
        "optional priors (as 'import asterix')",
    ),
    "--asterix": (
        "udp://HOST:PORT",
        "an ASTERIX input (CAT048 plots, CAT034, CAT021 ADS-B); repeat for several; a multicast HOST is "
        "joined; port 0: any free port, printed",
    ),
    "--nmea": (
        "udp://HOST:PORT|tcp://HOST:PORT|tcp-listen://HOST:PORT",
        "one ship's bridge: NMEA 0183 lines with TTM, navigation and AIS, listened to over UDP, read from "
        "a multiplexer's TCP server that the service connects to (tcp://, again when it drops), or from "
        "TCP clients that connect to the service (tcp-listen://, e.g. 'replay --to tcp://'); needs "
        "--platform and --sensors",
    ),
    "--platform": ("NAME", "the ship of --nmea (its platform name, as 'import nmea --platform')"),
    "--sensors": (
        "SENSORS.csv",
        "the ship's sensors file with an optional talker column naming each radar's TTM talker "
        "(as 'import nmea --sensors')",
    ),
    "--interface": (
        "ADDRESS",
        "the IPv4 address of the interface that joins multicast groups (default 0.0.0.0: the system's)",
    ),
    "--http": ("HOST:PORT", "the page and the API (default 127.0.0.1:8063; port 0: any free port, printed)"),
    "--cat063": (
        "udp://HOST:PORT",
        "send ASTERIX CAT063 sensor status messages (edition 1.6/1.7) with the estimates here",
    ),
    "--cat063-period-s": ("S", "seconds between CAT063 messages (default 10)"),
    "--sac-sic": ("SAC/SIC", "this service's data source identifier in CAT063 (default 25/200)"),
    "--corrected": (
        "udp://HOST:PORT",
        "send every datagram received on, its CAT048 plots' range, azimuth and time corrected by the "
        "current estimates; with --nmea also every NMEA line, one per datagram, TTM range and bearing "
        "corrected",
    ),
    "--state": (
        "DIR",
        "checkpoint the estimator's state in DIR (atomically, every --checkpoint-s and at exit) and "
        "resume from it",
    ),
    "--checkpoint-s": ("S", "seconds between checkpoints (default 60)"),
    "--window-s": ("S", "the filter's epoch, the target windows (default 20 s of data)"),
    "--alarm-window-s": ("S", "the data a change test compares with the estimate before it (default 60 s)"),
    "--date": ("YYYY-MM-DD", "the UTC day the time axis counts from (default: today)"),
}
_TYPES = {"--config": Path, "--state": Path, "--cat063-period-s": float, "--checkpoint-s": float}
_TYPES.update({"--window-s": float, "--alarm-window-s": float, "--sites": Path, "--sensors": Path})


def add_arguments(p: argparse.ArgumentParser) -> None:
    from registration.cli.importing import CAT021_EDITIONS

    for option, (metavar, text) in _OPTIONS.items():
        kind = {"action": "append"} if option == "--asterix" else {"type": _TYPES.get(option, str)}
        p.add_argument(option, metavar=metavar, help=text, **kind)
    p.add_argument(
        "--cat021-edition",
        choices=CAT021_EDITIONS,
        metavar="EDITION",
        help="the CAT021 (ADS-B) edition of the feed (default: the latest)",
    )


def _sac_sic(text: str) -> tuple[int, int]:
    sac, sep, sic = str(text).partition("/")
    try:
        return int(sac), int(sic)
    except ValueError:
        raise ValueError(f"--sac-sic: {text!r} is not SAC/SIC (two numbers 0-255)") from None


def config_from_args(args: argparse.Namespace):
    """The :class:`~registration.live.config.ServeConfig` of the options and ``--config``."""
    from registration.live.config import Endpoint, ServeConfig, parse_host_port, read_config_file

    given = read_config_file(args.config) if args.config is not None else {}

    def pick(dest: str):
        value = getattr(args, dest, None)
        return value if value is not None else given.get(dest, _DEFAULTS.get(dest))

    sites = pick("sites")
    asterix = pick("asterix") or []
    asterix = [asterix] if isinstance(asterix, str) else asterix
    date = pick("date")
    optional = {k: pick(k) for k in ("cat063", "corrected")}
    return ServeConfig(
        sites=Path(sites) if sites is not None else None,
        asterix=tuple(Endpoint.parse(a, "--asterix") for a in asterix),
        nmea=Endpoint.parse(pick("nmea"), "--nmea", ("udp", "tcp", "tcp-listen")) if pick("nmea") else None,
        platform=str(pick("platform")) if pick("platform") is not None else None,
        sensors=Path(pick("sensors")) if pick("sensors") is not None else None,
        interface=str(pick("interface")),
        http=parse_host_port(pick("http"), "--http"),
        cat063=Endpoint.parse(optional["cat063"], "--cat063") if optional["cat063"] else None,
        cat063_period_s=float(pick("cat063_period_s")),
        sac_sic=_sac_sic(pick("sac_sic")),
        corrected=Endpoint.parse(optional["corrected"], "--corrected") if optional["corrected"] else None,
        state=Path(pick("state")) if pick("state") is not None else None,
        checkpoint_s=float(pick("checkpoint_s")),
        window_s=float(pick("window_s")),
        alarm_window_s=float(pick("alarm_window_s")),
        cat021_edition=pick("cat021_edition"),
        date=dt.date.fromisoformat(str(date)) if date else None,
    )


def run(args: argparse.Namespace) -> int:
    from registration.live.service import Service

    service = Service(config_from_args(args), log=lambda line: print(line, file=sys.stderr, flush=True))
    return service.run()
