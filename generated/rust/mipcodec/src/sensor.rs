//! Sensor (IMU) Data Set. Calibrated inertial sensor measurements.
//!
//! Descriptor set 0x80 (data set):
//! one struct per field layout, and `SetField`, the enum of all its fields.

/// Descriptor set of this module.
pub const SET: u8 = 0x80;

/// Scaled accelerometer vector. Sensed acceleration, temperature compensated, in g (1 g = 9.80665 m/s^2), X, Y, Z in the sensor (GX5-45) or vehicle (CV7) frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledAccel {
    /// (x, y, z) acceleration. Units: g.
    pub scaled_accel: [f32; 3],
}

impl Default for ScaledAccel {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledAccel {
    const ZERO: Self = Self {
        scaled_accel: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scaled_accel =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaled_accel"))?;
        Ok(Self {
            scaled_accel: p_scaled_accel,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scaled_accel;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaled_accel"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scaled_accel;
        crate::json::key(w, &mut first, "scaled_accel")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledAccel {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scaled_accel"])?;
        let p_scaled_accel = o.req(
            "scaled_accel",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scaled_accel: p_scaled_accel,
        })
    }
}

impl ScaledAccel {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for ScaledAccel {
    const DESCRIPTOR: u8 = 0x04;
    const NAME: &'static str = "scaled_accel";
}

/// Scaled gyro vector. Sensed angular rate, temperature compensated, in radians/second, X, Y, Z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledGyro {
    /// (x, y, z) angular rate. Units: rad/s.
    pub scaled_gyro: [f32; 3],
}

impl Default for ScaledGyro {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledGyro {
    const ZERO: Self = Self {
        scaled_gyro: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scaled_gyro =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaled_gyro"))?;
        Ok(Self {
            scaled_gyro: p_scaled_gyro,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scaled_gyro;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaled_gyro"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scaled_gyro;
        crate::json::key(w, &mut first, "scaled_gyro")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledGyro {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scaled_gyro"])?;
        let p_scaled_gyro = o.req(
            "scaled_gyro",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scaled_gyro: p_scaled_gyro,
        })
    }
}

impl ScaledGyro {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for ScaledGyro {
    const DESCRIPTOR: u8 = 0x05;
    const NAME: &'static str = "scaled_gyro";
}

/// Scaled magnetometer vector. Sensed magnetic field, temperature compensated, in Gauss, X, Y, Z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledMag {
    /// (x, y, z) magnetic field. Units: gauss.
    pub scaled_mag: [f32; 3],
}

impl Default for ScaledMag {
    fn default() -> Self {
        <Self as crate::wire::Wire>::ZERO
    }
}

impl crate::wire::Wire for ScaledMag {
    const ZERO: Self = Self {
        scaled_mag: <[f32; 3] as crate::wire::Wire>::ZERO,
    };
    const FIXED_SIZE: Option<usize> = Some(12);

    fn decode(r: &mut crate::wire::Reader<'_>) -> Result<Self, crate::error::DecodeError> {
        let p_scaled_mag =
            <[f32; 3] as crate::wire::Wire>::decode(r).map_err(|e| e.at("scaled_mag"))?;
        Ok(Self {
            scaled_mag: p_scaled_mag,
        })
    }

    fn encode(&self, w: &mut crate::wire::Writer<'_>) -> Result<(), crate::error::EncodeError> {
        let v = &self.scaled_mag;
        crate::wire::Wire::encode(v, w).map_err(|e| e.at("scaled_mag"))?;
        Ok(())
    }

    fn write_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        let mut first = true;
        w.write_str("{")?;
        let v = &self.scaled_mag;
        crate::json::key(w, &mut first, "scaled_mag")?;
        crate::wire::Wire::write_json(v, w)?;
        w.write_str("}")
    }
}

#[cfg(feature = "std")]
impl crate::json_read::FromJson for ScaledMag {
    fn from_json(v: &crate::json_read::Json) -> Result<Self, crate::json_read::JsonError> {
        let o = crate::json_read::Obj::new(v, &["scaled_mag"])?;
        let p_scaled_mag = o.req(
            "scaled_mag",
            <[f32; 3] as crate::json_read::FromJson>::from_json,
        )?;
        Ok(Self {
            scaled_mag: p_scaled_mag,
        })
    }
}

impl ScaledMag {
    /// Descriptor set of the field.
    pub const SET: u8 = 0x80;
}

impl crate::wire::Layout for ScaledMag {
    const DESCRIPTOR: u8 = 0x06;
    const NAME: &'static str = "scaled_mag";
}

/// A decoded field of set 0x80 (`sensor`).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SetField {
    /// `scaled_accel` (0x04).
    ScaledAccel(ScaledAccel),
    /// `scaled_gyro` (0x05).
    ScaledGyro(ScaledGyro),
    /// `scaled_mag` (0x06).
    ScaledMag(ScaledMag),
}

impl SetField {
    /// Field descriptor.
    pub fn descriptor(&self) -> u8 {
        match self {
            Self::ScaledAccel(_) => 0x04,
            Self::ScaledGyro(_) => 0x05,
            Self::ScaledMag(_) => 0x06,
        }
    }

    /// Field name as printed in JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Self::ScaledAccel(_) => "scaled_accel",
            Self::ScaledGyro(_) => "scaled_gyro",
            Self::ScaledMag(_) => "scaled_mag",
        }
    }

    /// Device of the layout used, for fields with per-device layouts.
    pub fn device(&self) -> Option<crate::Device> {
        match self {
            Self::ScaledAccel(_) => None,
            Self::ScaledGyro(_) => None,
            Self::ScaledMag(_) => None,
        }
    }

    /// Encodes the field data.
    pub fn encode_data(
        &self,
        w: &mut crate::wire::Writer<'_>,
    ) -> Result<(), crate::error::EncodeError> {
        match self {
            Self::ScaledAccel(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledGyro(v) => crate::wire::Layout::encode_data(v, w),
            Self::ScaledMag(v) => crate::wire::Layout::encode_data(v, w),
        }
    }

    /// Writes the canonical JSON of the values (`{...}`).
    pub fn write_values_json(&self, w: &mut dyn core::fmt::Write) -> core::fmt::Result {
        match self {
            Self::ScaledAccel(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledGyro(v) => crate::wire::Wire::write_json(v, w),
            Self::ScaledMag(v) => crate::wire::Wire::write_json(v, w),
        }
    }

    /// Decodes field `descriptor` of this set; `None` if the set has no such field.
    pub fn decode(
        descriptor: u8,
        data: &[u8],
        device: Option<crate::Device>,
    ) -> Option<Result<Self, crate::error::DecodeError>> {
        let _ = device;
        match descriptor {
            0x04 => {
                Some(<ScaledAccel as crate::wire::Layout>::decode_data(data).map(Self::ScaledAccel))
            }
            0x05 => {
                Some(<ScaledGyro as crate::wire::Layout>::decode_data(data).map(Self::ScaledGyro))
            }
            0x06 => {
                Some(<ScaledMag as crate::wire::Layout>::decode_data(data).map(Self::ScaledMag))
            }
            _ => None,
        }
    }

    /// Reads the values of field `descriptor` of this set; `None` if the set has no such field.
    #[cfg(feature = "std")]
    pub fn from_json(
        descriptor: u8,
        device: Option<crate::Device>,
        values: &crate::json_read::Json,
    ) -> Option<Result<Self, crate::json_read::JsonError>> {
        match descriptor {
            0x04 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledAccel as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledAccel),
            ),
            0x05 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledGyro as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledGyro),
            ),
            0x06 => Some(
                crate::dispatch::no_device(device)
                    .and_then(|()| {
                        <ScaledMag as crate::json_read::FromJson>::from_json(values)
                            .map_err(|e| e.at("values"))
                    })
                    .map(Self::ScaledMag),
            ),
            _ => None,
        }
    }
}
