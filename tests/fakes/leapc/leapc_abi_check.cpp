// Our declarations of LeapC (devices/leapc/leapc_abi.h) held to a real LeapC.h at compile time:
// every struct size and field offset the backend reads, every enum value it compares and the
// functions' signatures. Compiled only where CMake finds Ultraleap's header (tests/CMakeLists.txt);
// a mismatch is a build error naming the field.
#include <LeapC.h>

#include <cstddef>

#include "devices/leapc/leapc_abi.h"

namespace ours = lmc::devices::leapc;

#define LMC_SAME_SIZE(our, theirs) \
  static_assert(sizeof(ours::our) == sizeof(theirs), #our " size differs from " #theirs)
#define LMC_SAME_OFFSET(our, theirs, our_field, their_field)                     \
  static_assert(offsetof(ours::our, our_field) == offsetof(theirs, their_field), \
                #our "::" #our_field " is not where " #theirs "::" #their_field " is")
#define LMC_SAME_VALUE(our, theirs) \
  static_assert(static_cast<std::uint32_t>(ours::our) == static_cast<std::uint32_t>(theirs), #our " != " #theirs)

// Results.
LMC_SAME_VALUE(kSuccess, eLeapRS_Success);
LMC_SAME_VALUE(kUnknownError, eLeapRS_UnknownError);
LMC_SAME_VALUE(kInvalidArgument, eLeapRS_InvalidArgument);
LMC_SAME_VALUE(kInsufficientResources, eLeapRS_InsufficientResources);
LMC_SAME_VALUE(kInsufficientBuffer, eLeapRS_InsufficientBuffer);
LMC_SAME_VALUE(kTimeout, eLeapRS_Timeout);
LMC_SAME_VALUE(kNotConnected, eLeapRS_NotConnected);
LMC_SAME_VALUE(kHandshakeIncomplete, eLeapRS_HandshakeIncomplete);
LMC_SAME_VALUE(kUnexpectedClosed, eLeapRS_UnexpectedClosed);
LMC_SAME_VALUE(kConcurrentPoll, eLeapRS_ConcurrentPoll);
LMC_SAME_VALUE(kNotAvailable, eLeapRS_NotAvailable);
LMC_SAME_VALUE(kNotStreaming, eLeapRS_NotStreaming);
LMC_SAME_VALUE(kCannotOpenDevice, eLeapRS_CannotOpenDevice);
LMC_SAME_VALUE(kUnsupported, eLeapRS_Unsupported);
// Events.
LMC_SAME_VALUE(event::kConnection, eLeapEventType_Connection);
LMC_SAME_VALUE(event::kConnectionLost, eLeapEventType_ConnectionLost);
LMC_SAME_VALUE(event::kDevice, eLeapEventType_Device);
LMC_SAME_VALUE(event::kDeviceFailure, eLeapEventType_DeviceFailure);
LMC_SAME_VALUE(event::kPolicy, eLeapEventType_Policy);
LMC_SAME_VALUE(event::kTracking, eLeapEventType_Tracking);
LMC_SAME_VALUE(event::kLogEvent, eLeapEventType_LogEvent);
LMC_SAME_VALUE(event::kDeviceLost, eLeapEventType_DeviceLost);
LMC_SAME_VALUE(event::kDeviceStatusChange, eLeapEventType_DeviceStatusChange);
LMC_SAME_VALUE(event::kDroppedFrame, eLeapEventType_DroppedFrame);
LMC_SAME_VALUE(event::kTrackingMode, eLeapEventType_TrackingMode);
LMC_SAME_VALUE(event::kLogEvents, eLeapEventType_LogEvents);
// Modes, policies, statuses, connection states, hands, log severities, version parts.
LMC_SAME_VALUE(kModeDesktop, eLeapTrackingMode_Desktop);
LMC_SAME_VALUE(kModeHmd, eLeapTrackingMode_HMD);
LMC_SAME_VALUE(kModeScreenTop, eLeapTrackingMode_ScreenTop);
LMC_SAME_VALUE(kPolicyBackgroundFrames, eLeapPolicyFlag_BackgroundFrames);
LMC_SAME_VALUE(kPolicyOptimizeHmd, eLeapPolicyFlag_OptimizeHMD);
LMC_SAME_VALUE(kPolicyOptimizeScreenTop, eLeapPolicyFlag_OptimizeScreenTop);
LMC_SAME_VALUE(kConnectionConfigMultiDeviceAware, eLeapConnectionConfig_MultiDeviceAware);
LMC_SAME_VALUE(kStatusStreaming, eLeapDeviceStatus_Streaming);
LMC_SAME_VALUE(kStatusPaused, eLeapDeviceStatus_Paused);
LMC_SAME_VALUE(kStatusRobust, eLeapDeviceStatus_Robust);
LMC_SAME_VALUE(kStatusSmudged, eLeapDeviceStatus_Smudged);
LMC_SAME_VALUE(kStatusLowResource, eLeapDeviceStatus_LowResource);
LMC_SAME_VALUE(kStatusUnknownFailure, eLeapDeviceStatus_UnknownFailure);
LMC_SAME_VALUE(kStatusBadCalibration, eLeapDeviceStatus_BadCalibration);
LMC_SAME_VALUE(kStatusBadFirmware, eLeapDeviceStatus_BadFirmware);
LMC_SAME_VALUE(kStatusBadTransport, eLeapDeviceStatus_BadTransport);
LMC_SAME_VALUE(kStatusBadControl, eLeapDeviceStatus_BadControl);
LMC_SAME_VALUE(kServiceLowFps, eLeapServiceState_LowFpsDetected);
LMC_SAME_VALUE(kServicePoorPerformancePause, eLeapServiceState_PoorPerformancePause);
LMC_SAME_VALUE(kServiceTrackingErrorUnknown, eLeapServiceState_TrackingErrorUnknown);
LMC_SAME_VALUE(kConnectionNotConnected, eLeapConnectionStatus_NotConnected);
LMC_SAME_VALUE(kConnectionConnected, eLeapConnectionStatus_Connected);
LMC_SAME_VALUE(kConnectionHandshakeIncomplete, eLeapConnectionStatus_HandshakeIncomplete);
LMC_SAME_VALUE(kConnectionNotRunning, eLeapConnectionStatus_NotRunning);
LMC_SAME_VALUE(kHandLeft, eLeapHandType_Left);
LMC_SAME_VALUE(kHandRight, eLeapHandType_Right);
LMC_SAME_VALUE(kLogCritical, eLeapLogSeverity_Critical);
LMC_SAME_VALUE(kLogWarning, eLeapLogSeverity_Warning);
LMC_SAME_VALUE(kLogInformation, eLeapLogSeverity_Information);
LMC_SAME_VALUE(kVersionClientLibrary, eLeapVersionPart_ClientLibrary);
LMC_SAME_VALUE(kVersionServerLibrary, eLeapVersionPart_ServerLibrary);

// Structs: sizes and the offset of every field read or written.
LMC_SAME_SIZE(Vector, LEAP_VECTOR);
LMC_SAME_SIZE(Quaternion, LEAP_QUATERNION);
LMC_SAME_SIZE(Bone, LEAP_BONE);
LMC_SAME_OFFSET(Bone, LEAP_BONE, next_joint, next_joint);
LMC_SAME_SIZE(Digit, LEAP_DIGIT);
LMC_SAME_OFFSET(Digit, LEAP_DIGIT, bones, bones);
LMC_SAME_SIZE(Palm, LEAP_PALM);
LMC_SAME_OFFSET(Palm, LEAP_PALM, normal, normal);
LMC_SAME_OFFSET(Palm, LEAP_PALM, direction, direction);
LMC_SAME_SIZE(Hand, LEAP_HAND);
LMC_SAME_OFFSET(Hand, LEAP_HAND, type, type);
LMC_SAME_OFFSET(Hand, LEAP_HAND, confidence, confidence);
LMC_SAME_OFFSET(Hand, LEAP_HAND, palm, palm);
LMC_SAME_OFFSET(Hand, LEAP_HAND, digits, digits);
LMC_SAME_OFFSET(Hand, LEAP_HAND, arm, arm);
LMC_SAME_SIZE(FrameHeader, LEAP_FRAME_HEADER);
LMC_SAME_OFFSET(FrameHeader, LEAP_FRAME_HEADER, frame_id, frame_id);
LMC_SAME_OFFSET(FrameHeader, LEAP_FRAME_HEADER, timestamp, timestamp);
LMC_SAME_SIZE(TrackingEvent, LEAP_TRACKING_EVENT);
LMC_SAME_OFFSET(TrackingEvent, LEAP_TRACKING_EVENT, tracking_frame_id, tracking_frame_id);
LMC_SAME_OFFSET(TrackingEvent, LEAP_TRACKING_EVENT, nHands, nHands);
LMC_SAME_OFFSET(TrackingEvent, LEAP_TRACKING_EVENT, pHands, pHands);
LMC_SAME_OFFSET(TrackingEvent, LEAP_TRACKING_EVENT, framerate, framerate);
LMC_SAME_SIZE(DeviceRef, LEAP_DEVICE_REF);
LMC_SAME_OFFSET(DeviceRef, LEAP_DEVICE_REF, id, id);
LMC_SAME_SIZE(ConnectionEvent, LEAP_CONNECTION_EVENT);
LMC_SAME_SIZE(DeviceEvent, LEAP_DEVICE_EVENT);
LMC_SAME_OFFSET(DeviceEvent, LEAP_DEVICE_EVENT, device, device);
LMC_SAME_SIZE(DeviceFailureEvent, LEAP_DEVICE_FAILURE_EVENT);
LMC_SAME_OFFSET(DeviceFailureEvent, LEAP_DEVICE_FAILURE_EVENT, hDevice, hDevice);
LMC_SAME_SIZE(DeviceStatusChangeEvent, LEAP_DEVICE_STATUS_CHANGE_EVENT);
LMC_SAME_OFFSET(DeviceStatusChangeEvent, LEAP_DEVICE_STATUS_CHANGE_EVENT, last_status, last_status);
LMC_SAME_OFFSET(DeviceStatusChangeEvent, LEAP_DEVICE_STATUS_CHANGE_EVENT, status, status);
LMC_SAME_SIZE(PolicyEvent, LEAP_POLICY_EVENT);
LMC_SAME_OFFSET(PolicyEvent, LEAP_POLICY_EVENT, current_policy, current_policy);
LMC_SAME_SIZE(TrackingModeEvent, LEAP_TRACKING_MODE_EVENT);
LMC_SAME_OFFSET(TrackingModeEvent, LEAP_TRACKING_MODE_EVENT, current_tracking_mode, current_tracking_mode);
LMC_SAME_SIZE(DroppedFrameEvent, LEAP_DROPPED_FRAME_EVENT);
LMC_SAME_SIZE(LogEvent, LEAP_LOG_EVENT);
LMC_SAME_OFFSET(LogEvent, LEAP_LOG_EVENT, message, message);
LMC_SAME_SIZE(LogEvents, LEAP_LOG_EVENTS);
LMC_SAME_OFFSET(LogEvents, LEAP_LOG_EVENTS, events, events);
LMC_SAME_SIZE(DeviceInfo, LEAP_DEVICE_INFO);
LMC_SAME_OFFSET(DeviceInfo, LEAP_DEVICE_INFO, pid, pid);
LMC_SAME_OFFSET(DeviceInfo, LEAP_DEVICE_INFO, serial_length, serial_length);
LMC_SAME_OFFSET(DeviceInfo, LEAP_DEVICE_INFO, serial, serial);
// From 5.12 the config ends with a tracking origin; its `size` field tells LeapC how much of it the
// caller filled, so ours (the 5.4 layout, the default origin) need only be a prefix of theirs.
static_assert(sizeof(ours::ConnectionConfig) <= sizeof(LEAP_CONNECTION_CONFIG), "ConnectionConfig too big");
LMC_SAME_OFFSET(ConnectionConfig, LEAP_CONNECTION_CONFIG, flags, flags);
LMC_SAME_OFFSET(ConnectionConfig, LEAP_CONNECTION_CONFIG, server_namespace, server_namespace);
LMC_SAME_SIZE(ConnectionInfo, LEAP_CONNECTION_INFO);
LMC_SAME_OFFSET(ConnectionInfo, LEAP_CONNECTION_INFO, status, status);
LMC_SAME_SIZE(Version, LEAP_VERSION);
LMC_SAME_OFFSET(Version, LEAP_VERSION, patch, patch);
LMC_SAME_SIZE(ConnectionMessage, LEAP_CONNECTION_MESSAGE);
LMC_SAME_OFFSET(ConnectionMessage, LEAP_CONNECTION_MESSAGE, type, type);
LMC_SAME_OFFSET(ConnectionMessage, LEAP_CONNECTION_MESSAGE, event, pointer);
LMC_SAME_OFFSET(ConnectionMessage, LEAP_CONNECTION_MESSAGE, device_id, device_id);
