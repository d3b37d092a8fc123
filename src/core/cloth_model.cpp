#include "cloth_model.hpp"

namespace termpool::core {

ClothModel cloth_model(const FrictionModel& friction) {
    switch (friction.kind) {
    case FrictionKind::decay:
        return decay_cloth();
    case FrictionKind::constant:
        return constant_cloth();
    case FrictionKind::combined:
        return combined_cloth();
    case FrictionKind::physical:
        break;
    }
    return physical_cloth();
}

} // namespace termpool::core
