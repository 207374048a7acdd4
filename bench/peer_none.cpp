// The peer benchmark without optional engines: no build of them was given at configure time.

#include "peer_engines.h"

namespace peers {

std::vector<PeerEngine> optional_engines(unsigned /*threads*/) {
    return {};
}

}  // namespace peers
