// Appends to a queue with one atomicAdd per subgroup: the subgroup counts its wanting lanes
// with a ballot, one elected lane reserves that many slots, and each lane takes its slot by
// its rank among the wanting lanes. Must be called in uniform control flow by every lane.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require

#define WF_DEFINE_QUEUE_APPEND(functionName, counter)                                          \
    uint functionName(bool wants) {                                                            \
        uvec4 ballot = subgroupBallot(wants);                                                  \
        uint total = subgroupBallotBitCount(ballot);                                           \
        uint base = 0u;                                                                        \
        if (total > 0u) {                                                                      \
            if (subgroupElect())                                                               \
                base = atomicAdd(counter, total);                                              \
            base = subgroupBroadcastFirst(base);                                               \
        }                                                                                      \
        return base + subgroupBallotExclusiveBitCount(ballot);                                 \
    }

// The same for one of several queues: `counter` names an array of counters, indexed by queue.
#define WF_DEFINE_INDEXED_QUEUE_APPEND(functionName, counter)                                  \
    uint functionName(uint queue, bool wants) {                                                \
        uvec4 ballot = subgroupBallot(wants);                                                  \
        uint total = subgroupBallotBitCount(ballot);                                           \
        uint base = 0u;                                                                        \
        if (total > 0u) {                                                                      \
            if (subgroupElect())                                                               \
                base = atomicAdd(counter[queue], total);                                       \
            base = subgroupBroadcastFirst(base);                                               \
        }                                                                                      \
        return base + subgroupBallotExclusiveBitCount(ballot);                                 \
    }
