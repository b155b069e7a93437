// Runs the real `lmc record` binary: a simulated trial with ground truth that `lmc info` reads,
// the Vicon trigger to a loopback listener, a replay, and refusals.
#include <arpa/inet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace record_test {

using ::testing::HasSubstr;

using lmc::test::CliRun;
using lmc::test::read_text_file;
using lmc::test::run_lmc;

// The Vicon trigger keeps the last PacketID it used in a state file; these tests keep theirs in a
// folder of their own, never the user's (ctest runs these in parallel: the file is locked).
const bool kPrivateStateDir = [] {
  const auto dir = lmc::test::scratch_dir("state");
  ::setenv("LMC_STATE_DIR", dir.c_str(), 1);
  return true;
}();

CliRun run(const std::string& args, const std::filesystem::path& logs) {
  return run_lmc(args, logs);
}

// `lmc <args>` under `ulimit -f <blocks>` (the shell's file-size limit).
CliRun run_with_file_limit(int blocks, const std::string& args, const std::filesystem::path& logs) {
  return run_lmc(args, logs, "ulimit -f " + std::to_string(blocks) + " &&");
}

nlohmann::json json_file(const std::filesystem::path& p) {
  return nlohmann::json::parse(read_text_file(p));
}

TEST(LmcRecord, SimulatedTrialWritesRecordingSidecarAndTruthThatInfoReads) {
  const auto dir = lmc::test::scratch_dir("record_sim");
  const CliRun r =
      run("record --backend sim --layout paper-initial --trial S01_index_1 --seconds 4 --motion index "
          "--fast --seed 5 -o " +
              lmc::test::shell_quote((dir / "session").string()),
          dir / "logs");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("trial S01_index_1:"));
  const auto rec = dir / "session" / "LMC_S01_index_1.raw.txt";
  const auto side = dir / "session" / "LMC_S01_index_1.session.json";
  const auto trc = dir / "session" / "S01_index_1.trc";
  ASSERT_TRUE(std::filesystem::exists(rec));
  ASSERT_TRUE(std::filesystem::exists(side));
  ASSERT_TRUE(std::filesystem::exists(trc));

  const CliRun info = run("info --json " + lmc::test::shell_quote(rec.string()), dir / "info");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto ij = nlohmann::json::parse(info.out);
  EXPECT_EQ(ij.at("variant"), "raw");
  EXPECT_EQ(ij.at("device_ids"), nlohmann::json({1, 2, 3, 4}));
  const auto sj = json_file(side);
  EXPECT_EQ(sj.at("status"), "completed");
  EXPECT_EQ(sj.at("trial"), "S01_index_1");
  EXPECT_EQ(sj.at("frames_written"), ij.at("rows"));
  EXPECT_EQ(sj.at("frames_dropped"), 0);
  EXPECT_EQ(sj.at("serial_to_slot").size(), 4u);
  EXPECT_EQ(sj.at("extra").at("simulator").at("seed"), 5);
  EXPECT_EQ(sj.at("extra").at("simulator").at("motion"), "horizontal/index");
  for (const auto& d : ij.at("devices")) {
    // Each device streams at 11–34 Hz; its row count in the file equals the sidecar's.
    EXPECT_GE(d.at("rows").get<int>(), 11 * 4 - 8);
    EXPECT_LE(d.at("rows").get<int>(), 34 * 4 + 2);
    bool found = false;
    for (const auto& sd : sj.at("devices"))
      if (sd.at("device_id") == d.at("id")) {
        found = true;
        EXPECT_EQ(sd.at("frames_written"), d.at("rows"));
      }
    EXPECT_TRUE(found);
  }
  const CliRun tinfo = run("info --json " + lmc::test::shell_quote(trc.string()), dir / "tinfo");
  ASSERT_EQ(tinfo.exit_code, 0) << tinfo.err;
  const auto tj = nlohmann::json::parse(tinfo.out);
  EXPECT_EQ(tj.at("type"), "trc");
  EXPECT_EQ(tj.at("markers"), 26);
  EXPECT_EQ(tj.at("frames"), 400);
  EXPECT_EQ(tj.at("data_rate_hz"), 100.0);
  EXPECT_EQ(sj.at("ground_truth").at("file"), "S01_index_1.trc");

  // Same seed, same trial: the simulator is reproducible through the CLI too.
  const CliRun again =
      run("record --backend sim --trial S01_index_1 --seconds 4 --motion index --fast --seed 5 "
          "--quiet -o " +
              lmc::test::shell_quote((dir / "again").string()),
          dir / "logs2");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(read_text_file(dir / "again" / "LMC_S01_index_1.raw.txt") == read_text_file(rec));
  // The TRC's first line names its own path; everything after it must match.
  const std::string t1 = read_text_file(trc), t2 = read_text_file(dir / "again" / "S01_index_1.trc");
  EXPECT_TRUE(t1.substr(t1.find('\n')) == t2.substr(t2.find('\n')));
}

TEST(LmcRecord, SendsTheViconTriggerToALoopbackListener) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  socklen_t len = sizeof addr;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  const int port = ntohs(addr.sin_port);

  const auto dir = lmc::test::scratch_dir("record_vicon");
  const CliRun r =
      run("record --backend sim --trial Vic_1 --seconds 1 --quiet --vicon 127.0.0.1:" + std::to_string(port) +
              " --vicon-database " + lmc::test::shell_quote("D:/lab & co") + " -o " +
              lmc::test::shell_quote((dir / "s").string()),
          dir / "logs");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> packets;
  char buf[4096];
  pollfd p{fd, POLLIN, 0};
  while (::poll(&p, 1, 200) > 0) {
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n > 0) packets.emplace_back(buf, static_cast<size_t>(n));
  }
  ::close(fd);
  ASSERT_EQ(packets.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    const std::string& pk = packets[static_cast<size_t>(i)];
    EXPECT_EQ(pk.back(), '\0');
    EXPECT_THAT(pk, HasSubstr(i < 3 ? "<CaptureStart>" : "<CaptureStop RESULT=\"SUCCESS\">"));
    EXPECT_THAT(pk, HasSubstr("<Name VALUE=\"Vic_1\"/>"));
    EXPECT_THAT(pk, HasSubstr("<DatabasePath VALUE=\"D:/lab &amp; co\"/>"));
  }
  EXPECT_EQ(packets[0], packets[2]) << "repeats share the PacketID";
  EXPECT_NE(packets[0], packets[3]);
  const auto sj = json_file(dir / "s" / "LMC_Vic_1.session.json");
  ASSERT_EQ(sj.at("vicon_packets").size(), 2u);
  EXPECT_EQ(sj["vicon_packets"][0].at("type"), "CaptureStart");
  // Increasing (+1 unless another lmc on this host sent a packet in between: IDs are unique per host).
  EXPECT_GT(sj["vicon_packets"][1].at("packet_id").get<long long>(),
            sj["vicon_packets"][0].at("packet_id").get<long long>());

  // Alignment: at CaptureStart every device's clock is tied to the host instant it was sent.
  const auto& al = sj.at("vicon_alignment");
  EXPECT_EQ(al.at("event"), "CaptureStart sent");
  EXPECT_EQ(al.at("packet_id"), sj["vicon_packets"][0].at("packet_id"));
  EXPECT_GE(al.at("host_ns").get<long long>(), sj.at("host_start_ns").get<long long>());
  EXPECT_LE(al.at("host_ns").get<long long>(), sj.at("host_stop_ns").get<long long>());
  ASSERT_EQ(al.at("devices").size(), 4u);
  for (const auto& d : al.at("devices")) {
    // Vicon starts only when every device streams, so each has a latest frame.
    ASSERT_TRUE(d.at("latest_timestamp_us").is_number_integer()) << d.dump();
    const long long latest = d.at("latest_timestamp_us").get<long long>();
    const long long at_event = d.at("device_clock_at_event_us").get<long long>();
    EXPECT_GE(d.at("host_ns_since_latest").get<long long>(), 0) << d.dump();
    EXPECT_GE(at_event, latest);
    EXPECT_LT(at_event - latest, 1'000'000) << "the latest frame is less than a second old";
    // The simulator's clock is read, not extrapolated from the latest frame; the extrapolation
    // beside it misses only how late that frame was delivered (the simulator adds no capture
    // latency), so the read clock is at or after it.
    EXPECT_EQ(d.at("device_clock_method"), "read") << d.dump();
    const long long extrapolated = d.at("device_clock_extrapolated_us").get<long long>();
    EXPECT_EQ(extrapolated - latest, (d.at("host_ns_since_latest").get<long long>() + 500) / 1000);
    EXPECT_GE(at_event, extrapolated - 1) << d.dump();
    EXPECT_LT(at_event - extrapolated, 1'000'000) << d.dump();
    // It lies within the device's recorded span (the recording started before CaptureStart).
    bool found = false;
    for (const auto& sd : sj.at("devices"))
      if (sd.at("slot") == d.at("slot")) {
        found = true;
        EXPECT_GE(latest, sd.at("first_timestamp_us").get<long long>());
        EXPECT_LE(latest, sd.at("last_timestamp_us").get<long long>());
        EXPECT_EQ(sd.at("serial"), d.at("serial"));
      }
    EXPECT_TRUE(found) << d.dump();
  }
}

TEST(LmcRecord, ARefusedViconTriggerAbortsTheTrialAndTheSidecarSaysWhy) {
  // Nobody listens on the loopback discard port: the kernel refuses, a later send reports it.
  const auto dir = lmc::test::scratch_dir("record_vicon_refused");
  const CliRun r = run("record --backend sim --trial Refused --seconds 2 --quiet --vicon 127.0.0.1:9 -o " +
                           lmc::test::shell_quote((dir / "s").string()),
                       dir / "logs");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("refused"));
  const auto side = dir / "s" / "LMC_Refused.session.json";
  ASSERT_TRUE(std::filesystem::exists(side));
  const auto sj = json_file(side);
  EXPECT_EQ(sj.at("status"), "aborted");
  EXPECT_THAT(sj.at("error").get<std::string>(), HasSubstr("refused"));
  EXPECT_THAT(sj.at("error").get<std::string>(), HasSubstr("127.0.0.1:9"));
  bool packet_error = false;
  for (const auto& p : sj.at("vicon_packets")) packet_error = packet_error || p.contains("error");
  EXPECT_TRUE(packet_error);
  // lmc info reads the aborted sidecar and shows the reason.
  const CliRun info = run("info " + lmc::test::shell_quote(side.string()), dir / "info");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("status:     aborted"));
  EXPECT_THAT(info.out, HasSubstr("refused"));
}

TEST(LmcRecord, InfoDescribesTheSidecar) {
  const auto dir = lmc::test::scratch_dir("record_info_sidecar");
  const CliRun r =
      run("record --backend sim --layout paper-optimized --trial S02_thumb_1 --seconds 3 --motion thumb "
          "--fast --seed 3 --quiet -o " +
              lmc::test::shell_quote(dir.string()),
          dir / "logs");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto side = dir / "LMC_S02_thumb_1.session.json";
  const auto sj = json_file(side);

  const CliRun j = run("info --json " + lmc::test::shell_quote(side.string()), dir / "info_json");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto ij = nlohmann::json::parse(j.out);
  EXPECT_EQ(ij.at("type"), "session");
  EXPECT_EQ(ij.at("trial"), "S02_thumb_1");
  EXPECT_EQ(ij.at("status"), "completed");
  EXPECT_TRUE(ij.at("error").is_null());
  EXPECT_EQ(ij.at("backend"), "sim");
  EXPECT_EQ(ij.at("recording_file"), "LMC_S02_thumb_1.raw.txt");
  EXPECT_EQ(ij.at("layout_name"), sj.at("layout").at("name"));
  EXPECT_EQ(ij.at("layout_device_count"), 4);
  EXPECT_EQ(ij.at("serial_to_slot"), sj.at("serial_to_slot"));
  EXPECT_EQ(ij.at("serial_to_slot").size(), 4u);
  EXPECT_EQ(ij.at("frames_written"), sj.at("frames_written"));
  EXPECT_EQ(ij.at("frames_dropped"), 0);
  EXPECT_EQ(ij.at("host_start_utc"), sj.at("host_start_utc"));
  EXPECT_EQ(ij.at("host_stop_utc"), sj.at("host_stop_utc"));
  EXPECT_GT(ij.at("duration_s").get<double>(), 0.0);
  EXPECT_TRUE(ij.at("vicon_packets").empty());
  EXPECT_EQ(ij.at("ground_truth").at("file"), "S02_thumb_1.trc");
  EXPECT_TRUE(ij.at("warnings").empty()) << ij.at("warnings").dump();
  ASSERT_EQ(ij.at("devices").size(), 4u);
  long long sum = 0;
  for (size_t i = 0; i < 4; ++i) {
    const auto& d = ij.at("devices")[i];
    const auto& sd = sj.at("devices")[i];
    EXPECT_EQ(d.at("slot"), sd.at("slot"));
    EXPECT_EQ(d.at("serial"), sd.at("serial"));
    EXPECT_EQ(d.at("frames_written"), sd.at("frames_written"));
    EXPECT_EQ(d.at("gaps"), 0);
    EXPECT_EQ(d.at("disconnects"), 0);
    sum += d.at("frames_written").get<long long>();
  }
  EXPECT_EQ(sum, sj.at("frames_written").get<long long>());

  const CliRun t = run("info " + lmc::test::shell_quote(side.string()), dir / "info_text");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_THAT(t.out, HasSubstr("type:       session sidecar"));
  EXPECT_THAT(t.out, HasSubstr("trial:      S02_thumb_1"));
  EXPECT_THAT(t.out, HasSubstr("status:     completed"));
  EXPECT_THAT(t.out, HasSubstr("LMC4"));
  EXPECT_THAT(t.out, HasSubstr(sj.at("serial_to_slot").begin().key()));
  EXPECT_THAT(t.out, HasSubstr("warnings:   none"));
  // A layout still reads as a layout.
  const CliRun lay = run("info " + lmc::test::shell_quote(lmc::test::asset_file("layouts/paper-initial.json").string()),
                         dir / "info_layout");
  ASSERT_EQ(lay.exit_code, 0) << lay.err;
  EXPECT_THAT(lay.out, HasSubstr("type:       layout"));
}

TEST(LmcRecord, AFileSizeLimitStopsTheTrialWithAClearMessageAndKeepsTheRows) {
  // `ulimit -f`: without SIGXFSZ ignored the kernel would kill lmc mid-trial.
  const auto dir = lmc::test::scratch_dir("record_ulimit");
  const CliRun r = run_with_file_limit(
      200, "record --backend sim --trial big --seconds 120 --fast --quiet -o " + lmc::test::shell_quote(dir.string()),
      dir / "logs");
  ASSERT_EQ(r.exit_code, 1) << "lmc must exit with an error, not die of a signal; stderr: " << r.err;
  EXPECT_THAT(r.err, HasSubstr("File too large"));
  EXPECT_THAT(r.err, HasSubstr("ulimit -f"));
  EXPECT_THAT(r.err, HasSubstr("LMC_big.raw.txt"));
  EXPECT_THAT(r.err, HasSubstr("kept"));
  const auto rec = dir / "LMC_big.raw.txt";
  ASSERT_TRUE(std::filesystem::exists(rec));
  EXPECT_LE(std::filesystem::file_size(rec), 200u * 1024u);
  // What reached the file is still a readable recording.
  const CliRun info = run("info --json " + lmc::test::shell_quote(rec.string()), dir / "info");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto ij = nlohmann::json::parse(info.out);
  EXPECT_GT(ij.at("rows").get<int>(), 50);
  EXPECT_EQ(ij.at("device_count"), 4);
  // The sidecar says the trial failed and why.
  const auto sj = json_file(dir / "LMC_big.session.json");
  EXPECT_EQ(sj.at("status"), "failed");
  EXPECT_THAT(sj.at("error").get<std::string>(), HasSubstr("File too large"));
  EXPECT_EQ(sj.at("frames_written"), ij.at("rows")) << "the sidecar counts the rows the file holds";
}

// Sends `payload` to 127.0.0.1:port every 50 ms until `stop` (same PacketID: the listener keeps one),
// from `from` when given (127.0.0.2: another machine on the lab network).
void send_until(int port, const std::string& payload, const std::atomic<bool>& stop, const char* from = nullptr) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (from != nullptr) {
    sockaddr_in local{};
    local.sin_family = AF_INET;
    ::inet_pton(AF_INET, from, &local.sin_addr);
    if (::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0)
      ADD_FAILURE() << "cannot send from " << from;
  }
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  to.sin_port = htons(static_cast<uint16_t>(port));
  while (!stop) {
    ::sendto(fd, payload.data(), payload.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::close(fd);
}

std::string capture_message(bool start, const std::string& name, int packet_id) {
  std::string xml = R"(<?xml version="1.0" encoding="UTF-8" standalone="no" ?>)";
  xml += start ? "<CaptureStart>" : "<CaptureStop RESULT=\"SUCCESS\">";
  xml += "<Name VALUE=\"" + name + "\"/><DatabasePath VALUE=\"\"/><Delay VALUE=\"0\"/><PacketID VALUE=\"" +
         std::to_string(packet_id) + "\"/>";
  xml += start ? "</CaptureStart>" : "</CaptureStop>";
  xml.push_back('\0');
  return xml;
}

// A free loopback UDP port for lmc to listen on.
int free_udp_port() {
  const int probe = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(probe, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) return -1;
  socklen_t len = sizeof addr;
  ::getsockname(probe, reinterpret_cast<sockaddr*>(&addr), &len);
  ::close(probe);
  return ntohs(addr.sin_port);
}

// Fault drill: 64 KB of garbage, the largest datagram UDP carries, arrives on the
// listen port before and during the trial. The trial records as if it had not, and lmc says what
// it ignored.
TEST(LmcRecord, GarbageDatagramsOnTheListenPortAreIgnoredAndSaid) {
  const int port = free_udp_port();
  ASSERT_GT(port, 0);
  const auto dir = lmc::test::scratch_dir("record_listen_garbage");
  CliRun r;
  std::thread lmc([&] {
    r = run("record --backend sim --seconds 20 --vicon-listen " + std::to_string(port) +
                " --vicon-listen-address 127.0.0.1 -o " + lmc::test::shell_quote((dir / "s").string()),
            dir / "logs");
  });
  std::string garbage(65507, '\0');
  for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 2654435761u) >> 13);
  std::atomic<bool> stop_garbage{false};
  std::thread noise([&] { send_until(port, garbage, stop_garbage); });
  std::atomic<bool> stop_start{false};
  std::thread starter([&] { send_until(port, capture_message(true, "Naiv_Index103", 700), stop_start); });
  const auto side = dir / "s" / "LMC_Naiv_Index103.session.json";
  for (int i = 0; i < 400 && !std::filesystem::exists(side); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  stop_start = true;
  starter.join();
  std::atomic<bool> stop_stop{false};
  std::thread stopper([&] { send_until(port, capture_message(false, "Naiv_Index103", 701), stop_stop); });
  lmc.join();
  stop_stop = stop_garbage = true;
  stopper.join();
  noise.join();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto sj = json_file(side);
  EXPECT_EQ(sj.at("status"), "completed");
  EXPECT_EQ(sj.at("vicon_trigger_received").at("packet_id"), 700);
  EXPECT_EQ(sj.at("vicon_stop_received").at("packet_id"), 701);
  EXPECT_GT(sj.at("frames_written").get<int>(), 20);
  EXPECT_THAT(r.all(), HasSubstr("that are not Vicon capture messages (latest: 65507 bytes: "));
}

TEST(LmcRecord, ViconCaptureStartAndStopDriveTheTrial) {
  const int port = free_udp_port();
  ASSERT_GT(port, 0);

  const auto dir = lmc::test::scratch_dir("record_listen");
  CliRun r;
  std::thread lmc([&] {
    r = run("record --backend sim --seconds 20 --quiet --vicon-listen " + std::to_string(port) +
                " --vicon-listen-address 127.0.0.1 -o " + lmc::test::shell_quote((dir / "s").string()),
            dir / "logs");
  });
  std::atomic<bool> stop_start{false};
  std::thread starter([&] { send_until(port, capture_message(true, "Naiv_Thumb102", 900), stop_start); });
  // Recording begins at the first CaptureStart lmc hears; give it a second of frames.
  const auto side = dir / "s" / "LMC_Naiv_Thumb102.session.json";
  for (int i = 0; i < 200 && !std::filesystem::exists(side); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  stop_start = true;
  starter.join();
  std::atomic<bool> stop_stop{false};
  std::thread stopper([&] { send_until(port, capture_message(false, "Naiv_Thumb102", 901), stop_stop); });
  lmc.join();
  stop_stop = true;
  stopper.join();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(side));
  const auto sj = json_file(side);
  EXPECT_EQ(sj.at("status"), "completed");
  EXPECT_EQ(sj.at("trial"), "Naiv_Thumb102");
  EXPECT_EQ(sj.at("vicon_trigger_received").at("packet_id"), 900);
  EXPECT_EQ(sj.at("vicon_stop_received").at("packet_id"), 901);
  // The instant CaptureStart arrived ties every device clock to the Vicon capture.
  EXPECT_EQ(sj.at("vicon_alignment").at("event"), "CaptureStart received");
  EXPECT_EQ(sj.at("vicon_alignment").at("packet_id"), 900);
  EXPECT_EQ(sj.at("vicon_alignment").at("devices").size(), 4u);
  const CliRun info = run("info " + lmc::test::shell_quote(side.string()), dir / "info");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("CaptureStart 'Naiv_Thumb102' PacketID 900 received"));
  EXPECT_GT(sj.at("frames_written").get<int>(), 20);
  EXPECT_TRUE(std::filesystem::exists(dir / "s" / "Naiv_Thumb102.trc"));
}

// Only the lab's Vicon (--vicon-host) starts and stops the trial: a second host, 127.0.0.2, sending
// its own CaptureStart all along is refused and named on stderr, in the sidecar and by lmc info.
TEST(LmcRecord, OnlyTheViconHostGivenStartsTheTrialOthersAreRefusedAndNamed) {
  const int port = free_udp_port();
  ASSERT_GT(port, 0);
  const auto dir = lmc::test::scratch_dir("record_listen_host");
  CliRun r;
  std::thread lmc([&] {
    r = run("record --backend sim --seconds 20 --quiet --vicon-listen " + std::to_string(port) +
                " --vicon-host 127.0.0.1 -o " + lmc::test::shell_quote((dir / "s").string()),
            dir / "logs");
  });
  std::atomic<bool> stop_intruder{false};
  std::thread intruder([&] { send_until(port, capture_message(true, "Intruder", 500), stop_intruder, "127.0.0.2"); });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::atomic<bool> stop_start{false};
  std::thread starter([&] { send_until(port, capture_message(true, "Naiv_Wrist104", 600), stop_start); });
  const auto side = dir / "s" / "LMC_Naiv_Wrist104.session.json";
  for (int i = 0; i < 400 && !std::filesystem::exists(side); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  stop_start = true;
  starter.join();
  std::atomic<bool> stop_stop{false};
  std::thread stopper([&] { send_until(port, capture_message(false, "Naiv_Wrist104", 601), stop_stop); });
  lmc.join();
  stop_stop = stop_intruder = true;
  stopper.join();
  intruder.join();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s" / "LMC_Intruder.session.json"));
  EXPECT_THAT(r.err, HasSubstr("refused CaptureStart 'Intruder' (PacketID 500) from 127.0.0.2:"));
  EXPECT_THAT(r.err, HasSubstr(": not an allowed Vicon host (allowed: 127.0.0.1)"));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("any sender")));
  EXPECT_THAT(r.out, HasSubstr("vicon:     CaptureStart from 127.0.0.1 (listening on 0.0.0.0:" + std::to_string(port)));
  const auto sj = json_file(side);
  EXPECT_EQ(sj.at("status"), "completed");
  EXPECT_EQ(sj.at("vicon_trigger_received").at("packet_id"), 600);
  const auto& listen = sj.at("vicon_listen");
  EXPECT_EQ(listen.at("trigger_host"), "127.0.0.1");
  EXPECT_EQ(listen.at("allowed_senders"), "127.0.0.1");
  EXPECT_EQ(listen.at("any_sender"), false);
  const int refused = listen.at("refused_datagrams").get<int>();
  EXPECT_GT(refused, 0);
  EXPECT_EQ(listen.at("refused_senders").at("127.0.0.2"), refused);
  const CliRun info = run("info " + lmc::test::shell_quote(side.string()), dir / "info");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("vicon from: 127.0.0.1 (listening on 0.0.0.0:"));
  EXPECT_THAT(info.out, HasSubstr("refused:    " + std::to_string(refused) +
                                  " datagram(s) from other hosts: 127.0.0.2 x" + std::to_string(refused)));
  const CliRun info_json = run("info --json " + lmc::test::shell_quote(side.string()), dir / "info_json");
  ASSERT_EQ(info_json.exit_code, 0) << info_json.err;
  EXPECT_EQ(nlohmann::json::parse(info_json.out).at("vicon_listen").at("trigger_host"), "127.0.0.1");
}

TEST(LmcRecord, ABadViconHostListIsRefusedNamingTheEntry) {
  const auto dir = lmc::test::scratch_dir("record_listen_bad_host");
  const CliRun bad =
      run("record --backend sim --seconds 1 --vicon-listen 30999 --vicon-host '10.0.0.5, 10.0.0.300' -o " +
              lmc::test::shell_quote(dir.string()),
          dir / "bad");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_THAT(bad.err, HasSubstr("Vicon host list '10.0.0.5, 10.0.0.300': '10.0.0.300' is not an IPv4 address"));
  const CliRun alone = run("record --backend sim --trial t --seconds 1 --fast --vicon-host 127.0.0.1 -o " +
                               lmc::test::shell_quote(dir.string()),
                           dir / "alone");
  EXPECT_EQ(alone.exit_code, 1);
  EXPECT_THAT(alone.err, HasSubstr("--vicon-host and --vicon-listen-address apply to --vicon-listen"));
}

TEST(LmcRecord, ReplayKeepsEveryRowOfEveryDevice) {
  const auto path = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const auto dir = lmc::test::scratch_dir("record_replay");
  const CliRun r = run("record --backend " + lmc::test::shell_quote("replay:" + path.string()) +
                           " --trial again --seconds 30 --fast --quiet -o " + lmc::test::shell_quote(dir.string()),
                       dir / "logs");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CliRun info = run("info --json " + lmc::test::shell_quote((dir / "LMC_again.raw.txt").string()), dir / "info");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out);
  const int rows[] = {118, 121, 131, 130};
  ASSERT_EQ(j.at("devices").size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(j["devices"][static_cast<size_t>(i)].at("rows"), rows[i]);
}

TEST(LmcRecord, UnsafeTrialNamesAndExistingTrialsAreRefused) {
  const auto dir = lmc::test::scratch_dir("record_refuse");
  const CliRun bad =
      run("record --trial ../../etc/x --seconds 1 --fast -o " + lmc::test::shell_quote(dir.string()), dir / "l1");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_THAT(bad.err, HasSubstr("invalid trial name"));
  EXPECT_FALSE(std::filesystem::exists(dir / "LMC_.raw.txt"));
  const CliRun first =
      run("record --trial t1 --seconds 1 --fast --quiet -o " + lmc::test::shell_quote(dir.string()), dir / "l2");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const CliRun second =
      run("record --trial t1 --seconds 1 --fast --quiet -o " + lmc::test::shell_quote(dir.string()), dir / "l3");
  EXPECT_EQ(second.exit_code, 1);
  EXPECT_THAT(second.err, HasSubstr("exists"));
}

}  // namespace record_test
