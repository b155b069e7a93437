#pragma once
// The part of Ultraleap's LeapC C interface this backend uses, declared here in our own words from
// the public API reference (docs.ultraleap.com, LeapC guide and struct pages): the structs and
// fields it reads, the enum values it compares, and the signatures of the functions it looks up in
// the library at run time (leapc_library.h). Ultraleap's LeapC.h is not ours to ship, so nothing
// here includes it; where a real LeapC.h is present at build time, tests/fakes/leapc/
// leapc_abi_check.cpp holds every size, offset and value below to it.
//
// LeapC packs its structs to 1 byte and its enums are 4 bytes wide (the header asserts both), so
// the enums are plain 32-bit integers here. Gemini (LeapC 5) and Hyperion (LeapC 6) share every
// declaration below; devices/leapc/README.md says what was checked against which header.
#include <cstdint>

#if defined(_WIN32)
#define LMC_LEAPC_CALL __stdcall
#else
#define LMC_LEAPC_CALL
#endif

namespace lmc::devices::leapc {

using Result = std::uint32_t;  // eLeapRS
inline constexpr Result kSuccess = 0x00000000;
inline constexpr Result kUnknownError = 0xE2010000;
inline constexpr Result kInvalidArgument = 0xE2010001;
inline constexpr Result kInsufficientResources = 0xE2010002;
inline constexpr Result kInsufficientBuffer = 0xE2010003;
inline constexpr Result kTimeout = 0xE2010004;
inline constexpr Result kNotConnected = 0xE2010005;
inline constexpr Result kHandshakeIncomplete = 0xE2010006;
inline constexpr Result kUnexpectedClosed = 0xE201000A;
inline constexpr Result kConcurrentPoll = 0xE201000F;
inline constexpr Result kNotAvailable = 0xE7010002;
inline constexpr Result kNotStreaming = 0xE7010004;
inline constexpr Result kCannotOpenDevice = 0xE7010005;
inline constexpr Result kUnsupported = 0xE7010006;

// eLeapEventType: what a polled message holds.
namespace event {
inline constexpr std::uint32_t kNone = 0;
inline constexpr std::uint32_t kConnection = 1;
inline constexpr std::uint32_t kConnectionLost = 2;
inline constexpr std::uint32_t kDevice = 3;
inline constexpr std::uint32_t kDeviceFailure = 4;
inline constexpr std::uint32_t kPolicy = 5;
inline constexpr std::uint32_t kTracking = 0x100;
inline constexpr std::uint32_t kLogEvent = 0x103;
inline constexpr std::uint32_t kDeviceLost = 0x104;
inline constexpr std::uint32_t kDeviceStatusChange = 0x107;
inline constexpr std::uint32_t kDroppedFrame = 0x108;
inline constexpr std::uint32_t kTrackingMode = 0x10B;
inline constexpr std::uint32_t kLogEvents = 0x10C;
}  // namespace event

// eLeapTrackingMode.
inline constexpr std::uint32_t kModeDesktop = 0;
inline constexpr std::uint32_t kModeHmd = 1;
inline constexpr std::uint32_t kModeScreenTop = 2;

// eLeapPolicyFlag: background frames, and the two optimisations that are the tracking mode as the
// policy flags report it (neither = desktop).
inline constexpr std::uint32_t kPolicyBackgroundFrames = 0x00000001;
inline constexpr std::uint32_t kPolicyOptimizeHmd = 0x00000004;
inline constexpr std::uint32_t kPolicyOptimizeScreenTop = 0x00000100;

inline constexpr std::uint32_t kConnectionConfigMultiDeviceAware = 0x00000001;  // eLeapConnectionConfig

// eLeapDeviceStatus: bits while it works, codes from 0xE8010000 when it fails.
inline constexpr std::uint32_t kStatusStreaming = 0x00000001;
inline constexpr std::uint32_t kStatusPaused = 0x00000002;
inline constexpr std::uint32_t kStatusRobust = 0x00000004;
inline constexpr std::uint32_t kStatusSmudged = 0x00000008;
inline constexpr std::uint32_t kStatusLowResource = 0x00000010;
inline constexpr std::uint32_t kStatusUnknownFailure = 0xE8010000;
inline constexpr std::uint32_t kStatusBadCalibration = 0xE8010001;
inline constexpr std::uint32_t kStatusBadFirmware = 0xE8010002;
inline constexpr std::uint32_t kStatusBadTransport = 0xE8010003;
inline constexpr std::uint32_t kStatusBadControl = 0xE8010004;

// eLeapServiceDisposition (LEAP_CONNECTION_EVENT::flags).
inline constexpr std::uint32_t kServiceLowFps = 0x00000001;
inline constexpr std::uint32_t kServicePoorPerformancePause = 0x00000002;
inline constexpr std::uint32_t kServiceTrackingErrorUnknown = 0x00000004;

// eLeapConnectionStatus (LeapGetConnectionInfo).
inline constexpr std::uint32_t kConnectionNotConnected = 0;
inline constexpr std::uint32_t kConnectionConnected = 1;
inline constexpr std::uint32_t kConnectionHandshakeIncomplete = 2;
inline constexpr std::uint32_t kConnectionNotRunning = 0xE7030004;

// eLeapHandType.
inline constexpr std::uint32_t kHandLeft = 0;
inline constexpr std::uint32_t kHandRight = 1;

// eLeapLogSeverity.
inline constexpr std::uint32_t kLogCritical = 1;
inline constexpr std::uint32_t kLogWarning = 2;
inline constexpr std::uint32_t kLogInformation = 3;

// eLeapVersionPart.
inline constexpr std::uint32_t kVersionClientLibrary = 0;
inline constexpr std::uint32_t kVersionServerLibrary = 2;

struct OpaqueConnection;
struct OpaqueDevice;
using Connection = OpaqueConnection*;  // LEAP_CONNECTION
using Device = OpaqueDevice*;          // LEAP_DEVICE

#pragma pack(push, 1)

struct Vector {  // LEAP_VECTOR, mm
  float x, y, z;
};
struct Quaternion {  // LEAP_QUATERNION
  float x, y, z, w;
};
struct Bone {  // LEAP_BONE
  Vector prev_joint;
  Vector next_joint;
  float width;
  Quaternion rotation;
};
struct Digit {  // LEAP_DIGIT: metacarpal, proximal, intermediate, distal
  std::int32_t finger_id;
  Bone bones[4];
  std::uint32_t is_extended;
};
struct Palm {  // LEAP_PALM
  Vector position;
  Vector stabilized_position;
  Vector velocity;
  Vector normal;
  float width;
  Vector direction;
  Quaternion orientation;
};
struct Hand {  // LEAP_HAND
  std::uint32_t id;
  std::uint32_t flags;
  std::uint32_t type;  // kHandLeft / kHandRight
  float confidence;
  std::uint64_t visible_time;
  float pinch_distance;
  float grab_angle;
  float pinch_strength;
  float grab_strength;
  Palm palm;
  Digit digits[5];  // thumb, index, middle, ring, pinky
  Bone arm;
};
struct FrameHeader {  // LEAP_FRAME_HEADER
  void* reserved;
  std::int64_t frame_id;
  std::int64_t timestamp;  // µs, LeapGetNow()'s clock
};
struct TrackingEvent {  // LEAP_TRACKING_EVENT
  FrameHeader info;
  std::int64_t tracking_frame_id;
  std::uint32_t nHands;
  Hand* pHands;
  float framerate;
};
struct DeviceRef {  // LEAP_DEVICE_REF
  void* handle;
  std::uint32_t id;
};
struct ConnectionEvent {  // LEAP_CONNECTION_EVENT
  std::uint32_t flags;
};
struct DeviceEvent {  // LEAP_DEVICE_EVENT (Device and DeviceLost)
  std::uint32_t flags;
  DeviceRef device;
  std::uint32_t status;
};
struct DeviceFailureEvent {  // LEAP_DEVICE_FAILURE_EVENT
  std::uint32_t status;
  Device hDevice;  // may be null
};
struct DeviceStatusChangeEvent {  // LEAP_DEVICE_STATUS_CHANGE_EVENT
  DeviceRef device;
  std::uint32_t last_status;
  std::uint32_t status;
};
struct PolicyEvent {  // LEAP_POLICY_EVENT
  std::uint32_t reserved;
  std::uint32_t current_policy;
};
struct TrackingModeEvent {  // LEAP_TRACKING_MODE_EVENT
  std::uint32_t reserved;
  std::uint32_t current_tracking_mode;
};
struct DroppedFrameEvent {  // LEAP_DROPPED_FRAME_EVENT
  std::int64_t frame_id;
  std::uint32_t type;
};
struct LogEvent {  // LEAP_LOG_EVENT
  std::uint32_t severity;
  std::int64_t timestamp;
  const char* message;
};
struct LogEvents {  // LEAP_LOG_EVENTS
  std::uint32_t nEvents;
  LogEvent* events;
};
struct DeviceInfo {  // LEAP_DEVICE_INFO
  std::uint32_t size;
  std::uint32_t status;
  std::uint32_t caps;
  std::uint32_t pid;
  std::uint32_t baseline;
  std::uint32_t serial_length;
  char* serial;
  float h_fov;
  float v_fov;
  std::uint32_t range;
};
// LEAP_CONNECTION_CONFIG as of 5.4; 5.12 appended a tracking origin, which LeapC leaves at its
// default when `size` says the caller's struct ends before it.
struct ConnectionConfig {
  std::uint32_t size;
  std::uint32_t flags;
  const char* server_namespace;
};
struct ConnectionInfo {  // LEAP_CONNECTION_INFO
  std::uint32_t size;
  std::uint32_t status;  // kConnection*
};
struct Version {  // LEAP_VERSION
  std::int32_t major;
  std::int32_t minor;
  std::int32_t patch;
};
// LEAP_CONNECTION_MESSAGE: `event` is the union of pointers to the event of `type`.
struct ConnectionMessage {
  std::uint32_t size;
  std::uint32_t type;
  const void* event;
  std::uint32_t device_id;  // the device a multi-device-aware connection's message is about (0: none)
};

#pragma pack(pop)

// The functions, as looked up by name.
using CreateConnectionFn = Result(LMC_LEAPC_CALL*)(const ConnectionConfig*, Connection*);
using OpenConnectionFn = Result(LMC_LEAPC_CALL*)(Connection);
using PollConnectionFn = Result(LMC_LEAPC_CALL*)(Connection, std::uint32_t timeout_ms, ConnectionMessage*);
using CloseConnectionFn = void(LMC_LEAPC_CALL*)(Connection);
using DestroyConnectionFn = void(LMC_LEAPC_CALL*)(Connection);
using GetConnectionInfoFn = Result(LMC_LEAPC_CALL*)(Connection, ConnectionInfo*);
using SetPolicyFlagsExFn = Result(LMC_LEAPC_CALL*)(Connection, Device, std::uint64_t set, std::uint64_t clear);
using SetTrackingModeExFn = Result(LMC_LEAPC_CALL*)(Connection, Device, std::uint32_t mode);
using GetTrackingModeExFn = Result(LMC_LEAPC_CALL*)(Connection, Device);
using OpenDeviceFn = Result(LMC_LEAPC_CALL*)(DeviceRef, Device*);
using CloseDeviceFn = void(LMC_LEAPC_CALL*)(Device);
using GetDeviceInfoFn = Result(LMC_LEAPC_CALL*)(Device, DeviceInfo*);
using SubscribeEventsFn = Result(LMC_LEAPC_CALL*)(Connection, Device);
using UnsubscribeEventsFn = Result(LMC_LEAPC_CALL*)(Connection, Device);
using GetNowFn = std::int64_t(LMC_LEAPC_CALL*)();
using GetVersionFn = Result(LMC_LEAPC_CALL*)(Connection, std::uint32_t part, Version*);

}  // namespace lmc::devices::leapc
