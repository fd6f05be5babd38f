// shared_census.h - the visibility census (render/census.h): per unique part, the pixels of
// the ID images of many views summed, the views that saw it and its largest count in one
// view. Part of shared.h's family (include shared.h).
// census.comp runs twice per view:
// - CENSUS_COUNT, one invocation per pixel in ID_PASS_TILE squares: adds each pixel to its
//   part's counter of this view (`viewAddress`, one uint per part);
// - CENSUS_FOLD, one invocation per part (workgroups of ID_PASS_TILE squared): moves this view's
// counter into the part's
//   CensusTotals and zeroes it for the next view.
// So the host reads back once, after the last view, whatever the number of views.
#ifndef IDVIEW_SHARED_CENSUS_H
#define IDVIEW_SHARED_CENSUS_H

IDV_CONST CENSUS_COUNT = 0u;
IDV_CONST CENSUS_FOLD = 1u;
struct CensusPush {
    uint64_t viewAddress;   // uint per part: this view's pixels
    uint64_t totalsAddress; // CensusTotals per part
    uvec2 extent;           // of the ID image
    uint parts;             // unique parts; IDs at or above (the background) are not counted
    uint step;              // CENSUS_COUNT or CENSUS_FOLD
};
struct CensusTotals {
    uint64_t pixels; // summed over the views
    uint views;      // views with at least one pixel of the part
    uint largest;    // the most pixels of the part in one view
};

#ifdef __cplusplus
static_assert(sizeof(CensusPush) == 32);
static_assert(sizeof(CensusTotals) == 16);
#endif

#endif
