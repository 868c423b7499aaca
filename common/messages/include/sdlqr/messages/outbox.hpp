#pragma once
// Where a process core puts the messages it publishes: one overload per message type (one type
// per channel), generated from lcmtypes/*.lcm (sdlqr/lcmtypes/generated/outbox.hpp, in the build
// folder). The bus publishes each on the channel of its type (common/bus core_binding.hpp); the
// in-process loop and the replay route it by the cores' declared ports (ports.hpp). Cores never
// see which.

#include "sdlqr/lcmtypes/generated/outbox.hpp"
#include "sdlqr/messages/messages.hpp"
