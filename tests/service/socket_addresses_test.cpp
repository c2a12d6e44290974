// SocketAddresses and UniqueFd: what the engine keeps per connection.

#include "service/socket_addresses.h"

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

TEST(SocketAddresses, OfANonIpSocketAreEmpty) {
  int pair[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
  const SocketAddresses addresses(pair[0]);
  EXPECT_EQ(addresses.peer().ip, "");
  EXPECT_EQ(addresses.peer().port, 0);
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
