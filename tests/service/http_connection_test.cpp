// ConnectionStream: what the HTTP library reads a framed request from and writes into; UniqueFd.

#include "service/http_connection.h"

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <thread>
#include <utility>

#include "service/unique_fd.h"

namespace cutcalc::service {
namespace {

TEST(ConnectionStream, ReadsTheRequestThenReportsItsEnd) {
  const SocketAddresses addresses(-1);
  std::string output;
  ConnectionStream stream("GET / HTTP/1.1\r\n\r\n", output, addresses);
  char buffer[8];
  EXPECT_TRUE(stream.is_readable());
  EXPECT_EQ(stream.read(buffer, sizeof buffer), 8);
  EXPECT_EQ(std::string(buffer, 8), "GET / HT");
  EXPECT_EQ(stream.read(buffer, sizeof buffer), 8);
  EXPECT_EQ(stream.read(buffer, sizeof buffer), 2);
  EXPECT_FALSE(stream.is_readable());
  // Past the request: the end of the stream, never a wait for the socket.
  EXPECT_EQ(stream.read(buffer, sizeof buffer), 0);
}

TEST(FramedRequestBody, IsTheThreadsBodyWhileItLivesAndRestoresTheOneBefore) {
  EXPECT_TRUE(framed_request_body().empty());
  {
    const FramedRequestBody outer("{\"a\": 1}");
    EXPECT_EQ(framed_request_body(), "{\"a\": 1}");
    {
      const FramedRequestBody inner("[]");
      EXPECT_EQ(framed_request_body(), "[]");
    }
    EXPECT_EQ(framed_request_body(), "{\"a\": 1}");
    std::string_view seen_elsewhere = "unset";
    std::thread([&seen_elsewhere] { seen_elsewhere = framed_request_body(); }).join();
    EXPECT_TRUE(seen_elsewhere.empty());  // one thread's request is not another's
  }
  EXPECT_TRUE(framed_request_body().empty());
}

TEST(ConnectionStream, GathersWritesIntoTheConnectionsOutput) {
  const SocketAddresses addresses(-1);
  std::string output = "HTTP/1.1 100 Continue\r\n\r\n";
  ConnectionStream stream("", output, addresses);
  EXPECT_EQ(stream.write("HTTP/1.1 200 OK\r\n", 17), 17);
  EXPECT_EQ(stream.write("\r\n", 2), 2);
  EXPECT_EQ(output, "HTTP/1.1 100 Continue\r\n\r\nHTTP/1.1 200 OK\r\n\r\n");
}

TEST(ConnectionStream, ShowsNoSocketSoTheLibraryNeverRefusesAHighDescriptor) {
  const SocketAddresses addresses(5000);
  std::string output;
  const ConnectionStream stream("", output, addresses);
  EXPECT_EQ(stream.socket(), INVALID_SOCKET);
}

TEST(ConnectionStream, AddressesOfANonIpSocketAreEmpty) {
  int pair[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
  const SocketAddresses addresses(pair[0]);
  std::string output;
  const ConnectionStream stream("", output, addresses);
  std::string ip = "unset";
  int port = -1;
  stream.get_remote_ip_and_port(ip, port);
  EXPECT_EQ(ip, "");
  EXPECT_EQ(port, 0);
  ::close(pair[0]);
  ::close(pair[1]);
}

bool is_open(int fd) { return ::fcntl(fd, F_GETFD) != -1; }

TEST(UniqueFd, ClosesOnceWhenItsLastOwnerGoes) {
  int pair[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
  ::close(pair[1]);
  const int fd = pair[0];
  {
    UniqueFd first(fd);
    UniqueFd second(std::move(first));
    EXPECT_FALSE(first.valid());  // NOLINT(bugprone-use-after-move): moved-from is empty
    EXPECT_EQ(second.get(), fd);
    EXPECT_TRUE(is_open(fd));
  }
  EXPECT_FALSE(is_open(fd));
}

TEST(UniqueFd, MoveAssignmentClosesWhatItHeld) {
  int pair[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
  UniqueFd held(pair[0]);
  held = UniqueFd(pair[1]);
  EXPECT_FALSE(is_open(pair[0]));
  EXPECT_TRUE(is_open(pair[1]));
}

}  // namespace
}  // namespace cutcalc::service
