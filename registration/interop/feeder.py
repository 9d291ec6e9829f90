"""Stone Soup detections corrected by a registration result.

A result is anything with ``layout.names`` (state names ``<platform>:heading_error``,
``<sensor>:range_bias``, ...), ``estimate`` (n,) and ``covariance`` (n, n): the batch
``BatchResult`` and the online fleet filter alike. For a detection of sensor s on platform P:

* **measurement**: ``corrected = measured - bias estimate`` per channel (range m, deck bearing
  and elevation rad), so Stone Soup's bearing gains the bearing bias (its sign is the opposite);
* **model**: the same model class with the sensor's pose rebuilt from the corrected attitude
  ``reported - attitude error estimate`` (the lever arm turned with it);
* **noise**: ``R + J P J^T``, R the model's noise, P the 6x6 covariance of P's three attitude
  errors and s's three biases, J = d plot / d(attitude errors, biases) from the generated
  ``fleet_residual`` at the corrected target position (``fleet_plot2ecef``; a 2-D detection is
  placed in the deck plane, elevation 0). A state the result
  holds fixed has zero covariance; a non-finite covariance (a state the data do not determine) is
  an error naming the states.

Detections of a sensor the result does not know, with an unsupported model or with a model
without pose are errors naming the sensor and model; nothing passes uncorrected.
"""

from __future__ import annotations

import copy

import numpy as np
from stonesoup.base import Property
from stonesoup.buffered_generator import BufferedGenerator
from stonesoup.feeder.base import DetectionFeeder
from stonesoup.types.array import CovarianceMatrix, StateVector

from registration._generated import api as generated
from registration.core.angles import wrap_angle
from registration.fleet.data.tables import ATTITUDE_ERRORS, CHANNELS, EXTENDED_ERRORS, read_table
from registration.interop.convert import (
    MODEL_CHANNELS,
    measured_plot,
    model_kind,
    model_pose,
    ss_covariance,
    ss_vector,
)
from registration.interop.requires import STONESOUP_VERSION
from registration.interop.world import LocalFrame

__all__ = ["STONESOUP_VERSION", "RegistrationCorrector", "RegisteredDetectionFeeder"]


class RegistrationCorrector:
    """Corrects single Stone Soup detections with a registration result (see the module docstring).

    ``sensors``: the sensors table (``sensor``, ``platform``, ``lever_x/y/z`` m) that maps each
    sensor to its platform and lever arm; ``frame``: Stone Soup's world
    (:class:`~registration.interop.world.LocalFrame`); ``sensor_key``: the detection metadata
    field naming the sensor; ``registration_noise``: add ``J P J^T`` to the noise.
    """

    def __init__(
        self,
        result,
        sensors,
        frame: LocalFrame,
        *,
        sensor_key: str = "sensor",
        registration_noise: bool = True,
    ):
        st = read_table("sensors", sensors, ("sensor", "platform"))
        lever = np.stack([st.floats(f"lever_{a}", default=0.0) for a in "xyz"], axis=1)
        self._sensors = {
            s: (str(p), lever[k]) for k, (s, p) in enumerate(zip(st.ids("sensor"), st.ids("platform")))
        }
        self.result = result
        self.names = list(result.layout.names)
        self.refresh()
        self.frame, self.sensor_key, self.registration_noise = frame, sensor_key, registration_noise

    def refresh(self) -> None:
        """Read the result's estimate and covariance again: a live result (the online filter,
        :class:`registration.fleet.FleetFilter`, updated between scans) corrects the next
        detections with what it knows by then."""
        estimate = np.asarray(self.result.estimate, dtype=float)
        covariance = np.asarray(self.result.covariance, dtype=float)
        if estimate.shape != (len(self.names),) or covariance.shape != (len(self.names),) * 2:
            raise ValueError(
                f"result: estimate {estimate.shape} and covariance {covariance.shape} do not "
                f"match the layout's {len(self.names)} states"
            )
        self.estimate, self.covariance = estimate, covariance

    def states(self, sensor: str, kind: type) -> list:
        """The indices (None where absent) of the sensor's platform's attitude errors and its biases."""
        if sensor not in self._sensors:
            raise ValueError(f"sensor {sensor!r}: not in the sensors table (known: {sorted(self._sensors)})")
        if not any(n.startswith(f"{sensor}:") for n in self.names):
            raise ValueError(
                f"sensor {sensor!r}: the registration result has no state of this sensor "
                f"(its states: {self.names})"
            )
        platform = self._sensors[sensor][0]
        att = [f"{platform}:{a}_error" for a in ATTITUDE_ERRORS]
        missing = [n for n in att if n not in self.names]
        if missing:
            raise ValueError(
                f"sensor {sensor!r}: the registration result has no {missing} of its platform {platform!r}"
            )
        extended = [
            n for n in self.names if n.split(":", 1)[0] == sensor and n.split(":", 1)[1] in EXTENDED_ERRORS
        ]
        if extended:
            raise ValueError(
                f"sensor {sensor!r}: the registration result models {extended}; the Stone Soup corrector "
                "applies attitude errors and biases only (range gain, time bias and position errors are "
                "not applied to detections yet): register this sensor without those columns"
            )
        bias = [f"{sensor}:{c}_bias" for c in CHANNELS]
        for name, measured in zip(bias, MODEL_CHANNELS[kind]):
            if measured and name not in self.names:
                raise ValueError(
                    f"sensor {sensor!r}: its {kind.__name__} measures the channel of {name!r}, "
                    "which the registration result does not hold"
                )
        return [self.names.index(n) if n in self.names else None for n in att + bias]

    def _values(self, index: list) -> tuple[np.ndarray, np.ndarray]:
        x = np.array([0.0 if i is None else self.estimate[i] for i in index])
        P = np.zeros((6, 6))
        held = [k for k, i in enumerate(index) if i is not None]
        P[np.ix_(held, held)] = self.covariance[np.ix_([index[k] for k in held], [index[k] for k in held])]
        return x, P

    def correct(self, detection):
        """A copy of ``detection`` with the corrected measurement vector and measurement model."""
        sensor = detection.metadata.get(self.sensor_key)
        if sensor is None:
            raise ValueError(
                f"detection at {detection.timestamp}: no metadata[{self.sensor_key!r}] naming its sensor"
            )
        sensor = str(sensor)
        model = detection.measurement_model
        kind = model_kind(model, sensor)
        p, orientation = model_pose(model, sensor)
        index = self.states(sensor, kind)
        x, P = self._values(index)
        lever = self._sensors[sensor][1]
        nav = self.frame.navigation(p, orientation, lever)[0]
        plot = measured_plot(detection, sensor)
        measured = np.where(np.isfinite(plot), plot, 0.0)
        corrected = measured - x[3:]
        corrected[1] = wrap_angle(corrected[1])
        fixed_nav = nav.copy()
        fixed_nav[3:] -= x[:3]
        fixed_nav[3] = wrap_angle(fixed_nav[3])
        p_world, orientation = self.frame.sensor_pose(fixed_nav, lever)
        size = np.asarray(model.translation_offset).size
        noise = np.asarray(model.covar(), dtype=float)
        if self.registration_noise:
            noise = noise + self._registration_noise(kind, sensor, index, nav, x, P, lever, measured)
        new_model = kind(
            ndim_state=model.ndim_state,
            mapping=model.mapping,
            noise_covar=CovarianceMatrix(noise),
            translation_offset=StateVector(p_world[0][:size]),
            rotation_offset=StateVector(orientation[0]),
        )
        out = copy.copy(detection)
        out.state_vector = ss_vector(kind, corrected)
        out.measurement_model = new_model
        out.metadata = dict(detection.metadata)
        return out

    def _registration_noise(self, kind, sensor, index, nav, x, P, lever, measured) -> np.ndarray:
        bad = [self.names[i] for k, i in enumerate(index) if i is not None and not np.isfinite(P[k]).all()]
        if bad:
            raise ValueError(
                f"sensor {sensor!r}: the registration covariance of {bad} is not finite (the data do not "
                "determine them); pass registration_noise=False to correct without it"
            )
        lat, lon, alt, heading, pitch, roll = nav
        r, q, e = measured
        ports = dict(lat=lat, lon=lon, alt=alt, heading=heading, pitch=pitch, roll=roll)
        ports.update(att_err=x[:3], bias=x[3:], lever_deck=lever, r=r, q=q, e=e)
        p_ecef = generated.fleet_plot2ecef(**ports).p_ecef
        J = generated.fleet_residual(p_ecef=p_ecef, **ports).J[0][:, 3:9]
        return ss_covariance(kind, J @ P @ J.T)


class RegisteredDetectionFeeder(DetectionFeeder):
    """A Stone Soup feeder that yields the detections of ``reader`` corrected by a registration
    result (see :class:`RegistrationCorrector`); an uncorrectable detection stops it with an error.
    The result is read again before every scan, so a live online filter can be passed and updated
    while the tracker runs."""

    result: object = Property(
        doc="Registration result: ``layout.names``, ``estimate`` (n,), ``covariance`` (n, n)"
    )
    sensors: object = Property(doc="Sensors table: sensor -> platform and lever arm (m, deck frame)")
    frame: LocalFrame = Property(doc="Stone Soup's world frame (registration.interop.world.LocalFrame)")
    sensor_key: str = Property(default="sensor", doc="Detection metadata field naming the sensor")
    registration_noise: bool = Property(
        default=True, doc="Add the registration uncertainty J P J^T to the noise"
    )

    @BufferedGenerator.generator_method
    def data_gen(self):
        corrector = RegistrationCorrector(
            self.result,
            self.sensors,
            self.frame,
            sensor_key=self.sensor_key,
            registration_noise=self.registration_noise,
        )
        for time, detections in self.reader:
            corrector.refresh()  # a live result may have moved since the last scan
            yield time, {corrector.correct(detection) for detection in detections}
