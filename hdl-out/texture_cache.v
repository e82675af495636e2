

module texture_cache(clock,inp_valid,inp_ready,inp_en,inp_addr0,inp_addr1,inp_addr2,inp_addr3,inp_side,inp_flush,out_valid,out_ready,out_data0,out_data1,out_data2,out_data3,out_side,mem$valid,mem$addr,mem$ack,mem$rvalid,mem$rdata,counters$hits,counters$misses,counters$fills);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  [3:0] inp_en;
    input wire  [25:0] inp_addr0;
    input wire  [25:0] inp_addr1;
    input wire  [25:0] inp_addr2;
    input wire  [25:0] inp_addr3;
    input wire  [63:0] inp_side;
    input wire  inp_flush;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [31:0] out_data0;
    output reg  [31:0] out_data1;
    output reg  [31:0] out_data2;
    output reg  [31:0] out_data3;
    output reg  [63:0] out_side;
    output reg  mem$valid;
    output reg  [25:0] mem$addr;
    input wire  mem$ack;
    input wire  mem$rvalid;
    input wire  [31:0] mem$rdata;
    output reg  [31:0] counters$hits;
    output reg  [31:0] counters$misses;
    output reg  [31:0] counters$fills;
    
    // Constant declarations
    localparam  word_last = 8'h3;
    localparam  line_base = 26'h3fffffc;
    
    // Stub signals
    reg  banks$0$clock;
    reg  [7:0] banks$0$rd_addr;
    reg  [25:0] banks$0$addr;
    reg  banks$0$fill;
    reg  [7:0] banks$0$word;
    reg  [31:0] banks$0$wdata;
    reg  banks$0$last;
    reg  banks$0$clear;
    reg  [5:0] banks$0$clear_set;
    wire  banks$0$hit;
    wire  [31:0] banks$0$data;
    reg  banks$1$clock;
    reg  [7:0] banks$1$rd_addr;
    reg  [25:0] banks$1$addr;
    reg  banks$1$fill;
    reg  [7:0] banks$1$word;
    reg  [31:0] banks$1$wdata;
    reg  banks$1$last;
    reg  banks$1$clear;
    reg  [5:0] banks$1$clear_set;
    wire  banks$1$hit;
    wire  [31:0] banks$1$data;
    reg  banks$2$clock;
    reg  [7:0] banks$2$rd_addr;
    reg  [25:0] banks$2$addr;
    reg  banks$2$fill;
    reg  [7:0] banks$2$word;
    reg  [31:0] banks$2$wdata;
    reg  banks$2$last;
    reg  banks$2$clear;
    reg  [5:0] banks$2$clear_set;
    wire  banks$2$hit;
    wire  [31:0] banks$2$data;
    reg  banks$3$clock;
    reg  [7:0] banks$3$rd_addr;
    reg  [25:0] banks$3$addr;
    reg  banks$3$fill;
    reg  [7:0] banks$3$word;
    reg  [31:0] banks$3$wdata;
    reg  banks$3$last;
    reg  banks$3$clear;
    reg  [5:0] banks$3$clear_set;
    wire  banks$3$hit;
    wire  [31:0] banks$3$data;
    reg  [1:0] st$d;
    wire  [1:0] st$q;
    reg  st$clock;
    reg  [5:0] clr$d;
    wire  [5:0] clr$q;
    reg  clr$clock;
    reg  flush_pend$d;
    wire  flush_pend$q;
    reg  flush_pend$clock;
    reg  s1_valid$d;
    wire  s1_valid$q;
    reg  s1_valid$clock;
    reg  s1_fresh$d;
    wire  s1_fresh$q;
    reg  s1_fresh$clock;
    reg  [3:0] s1_en$d;
    wire  [3:0] s1_en$q;
    reg  s1_en$clock;
    reg  [25:0] s1_addr$0$d;
    wire  [25:0] s1_addr$0$q;
    reg  s1_addr$0$clock;
    reg  [25:0] s1_addr$1$d;
    wire  [25:0] s1_addr$1$q;
    reg  s1_addr$1$clock;
    reg  [25:0] s1_addr$2$d;
    wire  [25:0] s1_addr$2$q;
    reg  s1_addr$2$clock;
    reg  [25:0] s1_addr$3$d;
    wire  [25:0] s1_addr$3$q;
    reg  s1_addr$3$clock;
    reg  [63:0] s1_side$d;
    wire  [63:0] s1_side$q;
    reg  s1_side$clock;
    reg  o_valid$d;
    wire  o_valid$q;
    reg  o_valid$clock;
    reg  [31:0] o_data$0$d;
    wire  [31:0] o_data$0$q;
    reg  o_data$0$clock;
    reg  [31:0] o_data$1$d;
    wire  [31:0] o_data$1$q;
    reg  o_data$1$clock;
    reg  [31:0] o_data$2$d;
    wire  [31:0] o_data$2$q;
    reg  o_data$2$clock;
    reg  [31:0] o_data$3$d;
    wire  [31:0] o_data$3$q;
    reg  o_data$3$clock;
    reg  [63:0] o_side$d;
    wire  [63:0] o_side$q;
    reg  o_side$clock;
    reg  [3:0] iss_mask$d;
    wire  [3:0] iss_mask$q;
    reg  iss_mask$clock;
    reg  [7:0] iss_word$d;
    wire  [7:0] iss_word$q;
    reg  iss_word$clock;
    reg  [3:0] rcv_mask$d;
    wire  [3:0] rcv_mask$q;
    reg  rcv_mask$clock;
    reg  [7:0] rcv_word$d;
    wire  [7:0] rcv_word$q;
    reg  rcv_word$clock;
    reg  [31:0] hits_r$d;
    wire  [31:0] hits_r$q;
    reg  hits_r$clock;
    reg  [31:0] misses_r$d;
    wire  [31:0] misses_r$q;
    reg  misses_r$clock;
    reg  [31:0] fills_r$d;
    wire  [31:0] fills_r$q;
    reg  fills_r$clock;
    
    // Local signals
    reg  run;
    reg  all_hit;
    reg  [3:0] miss_mask;
    reg  [31:0] n_hit;
    reg  [31:0] n_miss;
    reg  o_free;
    reg  s1_go;
    reg  pending;
    reg  take;
    reg  [1:0] iss_lane;
    reg  [25:0] iss_addr;
    reg  [1:0] rcv_lane;
    reg  rcv;
    reg  rcv_last;
    reg  [3:0] rcv_rest;
    
    // Sub module instances
    texture_cache$banks$0 banks$0(
        .clock(banks$0$clock),
        .rd_addr(banks$0$rd_addr),
        .addr(banks$0$addr),
        .fill(banks$0$fill),
        .word(banks$0$word),
        .wdata(banks$0$wdata),
        .last(banks$0$last),
        .clear(banks$0$clear),
        .clear_set(banks$0$clear_set),
        .hit(banks$0$hit),
        .data(banks$0$data)
    );
    texture_cache$banks$1 banks$1(
        .clock(banks$1$clock),
        .rd_addr(banks$1$rd_addr),
        .addr(banks$1$addr),
        .fill(banks$1$fill),
        .word(banks$1$word),
        .wdata(banks$1$wdata),
        .last(banks$1$last),
        .clear(banks$1$clear),
        .clear_set(banks$1$clear_set),
        .hit(banks$1$hit),
        .data(banks$1$data)
    );
    texture_cache$banks$2 banks$2(
        .clock(banks$2$clock),
        .rd_addr(banks$2$rd_addr),
        .addr(banks$2$addr),
        .fill(banks$2$fill),
        .word(banks$2$word),
        .wdata(banks$2$wdata),
        .last(banks$2$last),
        .clear(banks$2$clear),
        .clear_set(banks$2$clear_set),
        .hit(banks$2$hit),
        .data(banks$2$data)
    );
    texture_cache$banks$3 banks$3(
        .clock(banks$3$clock),
        .rd_addr(banks$3$rd_addr),
        .addr(banks$3$addr),
        .fill(banks$3$fill),
        .word(banks$3$word),
        .wdata(banks$3$wdata),
        .last(banks$3$last),
        .clear(banks$3$clear),
        .clear_set(banks$3$clear_set),
        .hit(banks$3$hit),
        .data(banks$3$data)
    );
    texture_cache$st st(
        .d(st$d),
        .q(st$q),
        .clock(st$clock)
    );
    texture_cache$clr clr(
        .d(clr$d),
        .q(clr$q),
        .clock(clr$clock)
    );
    texture_cache$flush_pend flush_pend(
        .d(flush_pend$d),
        .q(flush_pend$q),
        .clock(flush_pend$clock)
    );
    texture_cache$s1_valid s1_valid(
        .d(s1_valid$d),
        .q(s1_valid$q),
        .clock(s1_valid$clock)
    );
    texture_cache$s1_fresh s1_fresh(
        .d(s1_fresh$d),
        .q(s1_fresh$q),
        .clock(s1_fresh$clock)
    );
    texture_cache$s1_en s1_en(
        .d(s1_en$d),
        .q(s1_en$q),
        .clock(s1_en$clock)
    );
    texture_cache$s1_addr$0 s1_addr$0(
        .d(s1_addr$0$d),
        .q(s1_addr$0$q),
        .clock(s1_addr$0$clock)
    );
    texture_cache$s1_addr$1 s1_addr$1(
        .d(s1_addr$1$d),
        .q(s1_addr$1$q),
        .clock(s1_addr$1$clock)
    );
    texture_cache$s1_addr$2 s1_addr$2(
        .d(s1_addr$2$d),
        .q(s1_addr$2$q),
        .clock(s1_addr$2$clock)
    );
    texture_cache$s1_addr$3 s1_addr$3(
        .d(s1_addr$3$d),
        .q(s1_addr$3$q),
        .clock(s1_addr$3$clock)
    );
    texture_cache$s1_side s1_side(
        .d(s1_side$d),
        .q(s1_side$q),
        .clock(s1_side$clock)
    );
    texture_cache$o_valid o_valid(
        .d(o_valid$d),
        .q(o_valid$q),
        .clock(o_valid$clock)
    );
    texture_cache$o_data$0 o_data$0(
        .d(o_data$0$d),
        .q(o_data$0$q),
        .clock(o_data$0$clock)
    );
    texture_cache$o_data$1 o_data$1(
        .d(o_data$1$d),
        .q(o_data$1$q),
        .clock(o_data$1$clock)
    );
    texture_cache$o_data$2 o_data$2(
        .d(o_data$2$d),
        .q(o_data$2$q),
        .clock(o_data$2$clock)
    );
    texture_cache$o_data$3 o_data$3(
        .d(o_data$3$d),
        .q(o_data$3$q),
        .clock(o_data$3$clock)
    );
    texture_cache$o_side o_side(
        .d(o_side$d),
        .q(o_side$q),
        .clock(o_side$clock)
    );
    texture_cache$iss_mask iss_mask(
        .d(iss_mask$d),
        .q(iss_mask$q),
        .clock(iss_mask$clock)
    );
    texture_cache$iss_word iss_word(
        .d(iss_word$d),
        .q(iss_word$q),
        .clock(iss_word$clock)
    );
    texture_cache$rcv_mask rcv_mask(
        .d(rcv_mask$d),
        .q(rcv_mask$q),
        .clock(rcv_mask$clock)
    );
    texture_cache$rcv_word rcv_word(
        .d(rcv_word$d),
        .q(rcv_word$q),
        .clock(rcv_word$clock)
    );
    texture_cache$hits_r hits_r(
        .d(hits_r$d),
        .q(hits_r$q),
        .clock(hits_r$clock)
    );
    texture_cache$misses_r misses_r(
        .d(misses_r$d),
        .q(misses_r$q),
        .clock(misses_r$clock)
    );
    texture_cache$fills_r fills_r(
        .d(fills_r$d),
        .q(fills_r$q),
        .clock(fills_r$clock)
    );
    
    // Update code
    always @(*) begin
        st$clock = clock;
        clr$clock = clock;
        flush_pend$clock = clock;
        s1_valid$clock = clock;
        s1_fresh$clock = clock;
        s1_en$clock = clock;
        s1_side$clock = clock;
        o_valid$clock = clock;
        o_side$clock = clock;
        iss_mask$clock = clock;
        iss_word$clock = clock;
        rcv_mask$clock = clock;
        rcv_word$clock = clock;
        hits_r$clock = clock;
        misses_r$clock = clock;
        fills_r$clock = clock;
        st$d = st$q;
        clr$d = clr$q;
        flush_pend$d = flush_pend$q;
        s1_valid$d = s1_valid$q;
        s1_fresh$d = s1_fresh$q;
        s1_en$d = s1_en$q;
        s1_side$d = s1_side$q;
        o_valid$d = o_valid$q;
        o_side$d = o_side$q;
        iss_mask$d = iss_mask$q;
        iss_word$d = iss_word$q;
        rcv_mask$d = rcv_mask$q;
        rcv_word$d = rcv_word$q;
        hits_r$d = hits_r$q;
        misses_r$d = misses_r$q;
        fills_r$d = fills_r$q;
        s1_addr$0$clock = clock;
        s1_addr$0$d = s1_addr$0$q;
        o_data$0$clock = clock;
        o_data$0$d = o_data$0$q;
        banks$0$clock = clock;
        banks$0$addr = s1_addr$0$q;
        s1_addr$1$clock = clock;
        s1_addr$1$d = s1_addr$1$q;
        o_data$1$clock = clock;
        o_data$1$d = o_data$1$q;
        banks$1$clock = clock;
        banks$1$addr = s1_addr$1$q;
        s1_addr$2$clock = clock;
        s1_addr$2$d = s1_addr$2$q;
        o_data$2$clock = clock;
        o_data$2$d = o_data$2$q;
        banks$2$clock = clock;
        banks$2$addr = s1_addr$2$q;
        s1_addr$3$clock = clock;
        s1_addr$3$d = s1_addr$3$q;
        o_data$3$clock = clock;
        o_data$3$d = o_data$3$q;
        banks$3$clock = clock;
        banks$3$addr = s1_addr$3$q;
        run = st$q == 32'h1;
        all_hit = 1'b1;
        miss_mask = 32'h0;
        n_hit = 32'h0;
        n_miss = 32'h0;
        if (s1_en$q[0]) begin
            if (banks$0$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (0)) | ((1'b1) << (0)));
            end
        end
        if (s1_en$q[1]) begin
            if (banks$1$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (1)) | ((1'b1) << (1)));
            end
        end
        if (s1_en$q[2]) begin
            if (banks$2$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (2)) | ((1'b1) << (2)));
            end
        end
        if (s1_en$q[3]) begin
            if (banks$3$hit) begin
                n_hit = n_hit + 32'h1;
            end
            else begin
                n_miss = n_miss + 32'h1;
                all_hit = 1'b0;
                miss_mask = (miss_mask & ~(1 << (3)) | ((1'b1) << (3)));
            end
        end
        o_free = ~o_valid$q | out_ready;
        s1_go = run & s1_valid$q & all_hit & o_free;
        pending = flush_pend$q | inp_flush;
        inp_ready = run & ~pending & (~s1_valid$q | s1_go);
        take = inp_valid & inp_ready;
        banks$0$rd_addr = s1_addr$0$q[(32'h0)+:(8)];
        banks$1$rd_addr = s1_addr$1$q[(32'h0)+:(8)];
        banks$2$rd_addr = s1_addr$2$q[(32'h0)+:(8)];
        banks$3$rd_addr = s1_addr$3$q[(32'h0)+:(8)];
        s1_fresh$d = take;
        if (take) begin
            banks$0$rd_addr = inp_addr0[(32'h0)+:(8)];
            banks$1$rd_addr = inp_addr1[(32'h0)+:(8)];
            banks$2$rd_addr = inp_addr2[(32'h0)+:(8)];
            banks$3$rd_addr = inp_addr3[(32'h0)+:(8)];
            s1_valid$d = 1'b1;
            s1_en$d = inp_en;
            s1_addr$0$d = inp_addr0;
            s1_addr$1$d = inp_addr1;
            s1_addr$2$d = inp_addr2;
            s1_addr$3$d = inp_addr3;
            s1_side$d = inp_side;
        end
        else if (s1_go) begin
            s1_valid$d = 1'b0;
        end
        out_valid = o_valid$q;
        out_data0 = o_data$0$q;
        out_data1 = o_data$1$q;
        out_data2 = o_data$2$q;
        out_data3 = o_data$3$q;
        out_side = o_side$q;
        if (s1_go) begin
            o_valid$d = 1'b1;
            o_side$d = s1_side$q;
            o_data$0$d = 32'h0;
            if (s1_en$q[0]) begin
                o_data$0$d = banks$0$data;
            end
            o_data$1$d = 32'h0;
            if (s1_en$q[1]) begin
                o_data$1$d = banks$1$data;
            end
            o_data$2$d = 32'h0;
            if (s1_en$q[2]) begin
                o_data$2$d = banks$2$data;
            end
            o_data$3$d = 32'h0;
            if (s1_en$q[3]) begin
                o_data$3$d = banks$3$data;
            end
        end
        else if (out_ready) begin
            o_valid$d = 1'b0;
        end
        counters$hits = hits_r$q;
        counters$misses = misses_r$q;
        counters$fills = fills_r$q;
        if (run & s1_valid$q & s1_fresh$q) begin
            hits_r$d = hits_r$q + n_hit;
            misses_r$d = misses_r$q + n_miss;
        end
        flush_pend$d = pending;
        banks$0$clear = st$q == 32'h0;
        banks$0$clear_set = clr$q;
        banks$1$clear = st$q == 32'h0;
        banks$1$clear_set = clr$q;
        banks$2$clear = st$q == 32'h0;
        banks$2$clear_set = clr$q;
        banks$3$clear = st$q == 32'h0;
        banks$3$clear_set = clr$q;
        if (st$q == 32'h0) begin
            clr$d = clr$q + 32'h1;
            if (&clr$q) begin
                st$d = 32'h1;
            end
        end
        if (run) begin
            if (s1_valid$q & ~all_hit) begin
                st$d = 32'h2;
                iss_mask$d = miss_mask;
                rcv_mask$d = miss_mask;
                iss_word$d = 32'h0;
                rcv_word$d = 32'h0;
            end
            else if (pending & (~s1_valid$q | s1_go)) begin
                st$d = 32'h0;
                clr$d = 32'h0;
                flush_pend$d = 1'b0;
            end
        end
        if (st$q == 32'h3) begin
            st$d = 32'h1;
        end
        iss_lane = 32'h3;
        if (iss_mask$q[32'h2]) begin
            iss_lane = 32'h2;
        end
        if (iss_mask$q[32'h1]) begin
            iss_lane = 32'h1;
        end
        if (iss_mask$q[32'h0]) begin
            iss_lane = 32'h0;
        end
        iss_addr = s1_addr$0$q;
        if (iss_lane == 1) begin
            iss_addr = s1_addr$1$q;
        end
        if (iss_lane == 2) begin
            iss_addr = s1_addr$2$q;
        end
        if (iss_lane == 3) begin
            iss_addr = s1_addr$3$q;
        end
        mem$valid = (st$q == 32'h2) & |iss_mask$q;
        mem$addr = (iss_addr & line_base) | ((iss_word$q) & 26'h3ffffff);
        if (mem$valid & mem$ack) begin
            iss_word$d = iss_word$q + 32'h1;
            if (iss_word$q == word_last) begin
                iss_word$d = 32'h0;
                iss_mask$d = iss_mask$q & (iss_mask$q - 32'h1);
            end
        end
        rcv_lane = 32'h3;
        if (rcv_mask$q[32'h2]) begin
            rcv_lane = 32'h2;
        end
        if (rcv_mask$q[32'h1]) begin
            rcv_lane = 32'h1;
        end
        if (rcv_mask$q[32'h0]) begin
            rcv_lane = 32'h0;
        end
        rcv = (st$q == 32'h2) & |rcv_mask$q & mem$rvalid;
        rcv_last = rcv_word$q == word_last;
        rcv_rest = rcv_mask$q & (rcv_mask$q - 32'h1);
        banks$0$fill = 1'b0;
        if (rcv & (rcv_lane == 0)) begin
            banks$0$fill = 1'b1;
        end
        banks$0$word = rcv_word$q;
        banks$0$wdata = mem$rdata;
        banks$0$last = rcv_last;
        banks$1$fill = 1'b0;
        if (rcv & (rcv_lane == 1)) begin
            banks$1$fill = 1'b1;
        end
        banks$1$word = rcv_word$q;
        banks$1$wdata = mem$rdata;
        banks$1$last = rcv_last;
        banks$2$fill = 1'b0;
        if (rcv & (rcv_lane == 2)) begin
            banks$2$fill = 1'b1;
        end
        banks$2$word = rcv_word$q;
        banks$2$wdata = mem$rdata;
        banks$2$last = rcv_last;
        banks$3$fill = 1'b0;
        if (rcv & (rcv_lane == 3)) begin
            banks$3$fill = 1'b1;
        end
        banks$3$word = rcv_word$q;
        banks$3$wdata = mem$rdata;
        banks$3$last = rcv_last;
        if (rcv) begin
            rcv_word$d = rcv_word$q + 32'h1;
            if (rcv_last) begin
                rcv_word$d = 32'h0;
                rcv_mask$d = rcv_rest;
                fills_r$d = fills_r$q + 32'h1;
                if (~|rcv_rest) begin
                    st$d = 32'h3;
                end
            end
        end
    end
    
endmodule // texture_cache


module texture_cache$banks$0(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_cache$banks$0$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_cache$banks$0$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_cache$banks$0$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_cache$banks$0$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_cache$banks$0$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_cache$banks$0


module texture_cache$banks$0$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$0$tags$0


module texture_cache$banks$0$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$0$tags$1


module texture_cache$banks$0$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$0$victim


module texture_cache$banks$0$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$0$words$0


module texture_cache$banks$0$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$0$words$1


module texture_cache$banks$1(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_cache$banks$1$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_cache$banks$1$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_cache$banks$1$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_cache$banks$1$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_cache$banks$1$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_cache$banks$1


module texture_cache$banks$1$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$1$tags$0


module texture_cache$banks$1$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$1$tags$1


module texture_cache$banks$1$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$1$victim


module texture_cache$banks$1$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$1$words$0


module texture_cache$banks$1$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$1$words$1


module texture_cache$banks$2(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_cache$banks$2$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_cache$banks$2$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_cache$banks$2$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_cache$banks$2$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_cache$banks$2$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_cache$banks$2


module texture_cache$banks$2$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$2$tags$0


module texture_cache$banks$2$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$2$tags$1


module texture_cache$banks$2$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$2$victim


module texture_cache$banks$2$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$2$words$0


module texture_cache$banks$2$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$2$words$1


module texture_cache$banks$3(clock,rd_addr,addr,fill,word,wdata,last,clear,clear_set,hit,data);
    
    // Module arguments
    input wire  clock;
    input wire  [7:0] rd_addr;
    input wire  [25:0] addr;
    input wire  fill;
    input wire  [7:0] word;
    input wire  [31:0] wdata;
    input wire  last;
    input wire  clear;
    input wire  [5:0] clear_set;
    output reg  hit;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  set_at = 8'h2;
    localparam  tag_at = 8'h8;
    localparam  word_mask = 8'h3;
    localparam  way_mask = 2'b1;
    localparam  valid_bit = 19'b1;
    
    // Stub signals
    reg  [5:0] tags$0$read_address;
    reg  tags$0$read_clock;
    wire  [18:0] tags$0$read_data;
    reg  [5:0] tags$0$write_address;
    reg  tags$0$write_clock;
    reg  [18:0] tags$0$write_data;
    reg  tags$0$write_enable;
    reg  [5:0] tags$1$read_address;
    reg  tags$1$read_clock;
    wire  [18:0] tags$1$read_data;
    reg  [5:0] tags$1$write_address;
    reg  tags$1$write_clock;
    reg  [18:0] tags$1$write_data;
    reg  tags$1$write_enable;
    reg  [7:0] words$0$read_address;
    reg  words$0$read_clock;
    wire  [31:0] words$0$read_data;
    reg  [7:0] words$0$write_address;
    reg  words$0$write_clock;
    reg  [31:0] words$0$write_data;
    reg  words$0$write_enable;
    reg  [7:0] words$1$read_address;
    reg  words$1$read_clock;
    wire  [31:0] words$1$read_data;
    reg  [7:0] words$1$write_address;
    reg  words$1$write_clock;
    reg  [31:0] words$1$write_data;
    reg  words$1$write_enable;
    reg  [5:0] victim$read_address;
    reg  victim$read_clock;
    wire  [1:0] victim$read_data;
    reg  [5:0] victim$write_address;
    reg  victim$write_clock;
    reg  [1:0] victim$write_data;
    reg  victim$write_enable;
    
    // Local signals
    reg  [5:0] set;
    reg  [17:0] tag;
    reg  [1:0] way;
    reg  [18:0] tag_word;
    
    // Sub module instances
    texture_cache$banks$3$tags$0 tags$0(
        .read_address(tags$0$read_address),
        .read_clock(tags$0$read_clock),
        .read_data(tags$0$read_data),
        .write_address(tags$0$write_address),
        .write_clock(tags$0$write_clock),
        .write_data(tags$0$write_data),
        .write_enable(tags$0$write_enable)
    );
    texture_cache$banks$3$tags$1 tags$1(
        .read_address(tags$1$read_address),
        .read_clock(tags$1$read_clock),
        .read_data(tags$1$read_data),
        .write_address(tags$1$write_address),
        .write_clock(tags$1$write_clock),
        .write_data(tags$1$write_data),
        .write_enable(tags$1$write_enable)
    );
    texture_cache$banks$3$words$0 words$0(
        .read_address(words$0$read_address),
        .read_clock(words$0$read_clock),
        .read_data(words$0$read_data),
        .write_address(words$0$write_address),
        .write_clock(words$0$write_clock),
        .write_data(words$0$write_data),
        .write_enable(words$0$write_enable)
    );
    texture_cache$banks$3$words$1 words$1(
        .read_address(words$1$read_address),
        .read_clock(words$1$read_clock),
        .read_data(words$1$read_data),
        .write_address(words$1$write_address),
        .write_clock(words$1$write_clock),
        .write_data(words$1$write_data),
        .write_enable(words$1$write_enable)
    );
    texture_cache$banks$3$victim victim(
        .read_address(victim$read_address),
        .read_clock(victim$read_clock),
        .read_data(victim$read_data),
        .write_address(victim$write_address),
        .write_clock(victim$write_clock),
        .write_data(victim$write_data),
        .write_enable(victim$write_enable)
    );
    
    // Update code
    always @(*) begin
        victim$read_clock = clock;
        victim$write_clock = clock;
        victim$read_address = rd_addr[(set_at)+:(6)];
        tags$0$read_clock = clock;
        tags$0$write_clock = clock;
        words$0$read_clock = clock;
        words$0$write_clock = clock;
        tags$0$read_address = rd_addr[(set_at)+:(6)];
        words$0$read_address = rd_addr;
        tags$1$read_clock = clock;
        tags$1$write_clock = clock;
        words$1$read_clock = clock;
        words$1$write_clock = clock;
        tags$1$read_address = rd_addr[(set_at)+:(6)];
        words$1$read_address = rd_addr;
        set = addr[(set_at)+:(6)];
        tag = addr[(tag_at)+:(18)];
        hit = 1'b0;
        data = 32'h0;
        if (tags$0$read_data[32'h0] & (tags$0$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$0$read_data;
        end
        if (tags$1$read_data[32'h0] & (tags$1$read_data[(32'h1)+:(18)] == tag)) begin
            hit = 1'b1;
            data = words$1$read_data;
        end
        way = victim$read_data;
        tag_word = (((tag) & 19'h7ffff) << 32'h1) | valid_bit;
        victim$write_enable = clear | (fill & last);
        victim$write_address = set;
        victim$write_data = (way + 32'h1) & way_mask;
        if (clear) begin
            victim$write_address = clear_set;
            victim$write_data = 32'h0;
        end
        words$0$write_enable = 1'b0;
        tags$0$write_enable = clear;
        if (fill & (way == 0)) begin
            words$0$write_enable = 1'b1;
            tags$0$write_enable = last;
        end
        words$0$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$0$write_data = wdata;
        tags$0$write_address = set;
        tags$0$write_data = tag_word;
        if (clear) begin
            tags$0$write_address = clear_set;
            tags$0$write_data = 32'h0;
        end
        words$1$write_enable = 1'b0;
        tags$1$write_enable = clear;
        if (fill & (way == 1)) begin
            words$1$write_enable = 1'b1;
            tags$1$write_enable = last;
        end
        words$1$write_address = (addr[(32'h0)+:(8)] & ~word_mask) | word;
        words$1$write_data = wdata;
        tags$1$write_address = set;
        tags$1$write_data = tag_word;
        if (clear) begin
            tags$1$write_address = clear_set;
            tags$1$write_data = 32'h0;
        end
    end
    
endmodule // texture_cache$banks$3


module texture_cache$banks$3$tags$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$3$tags$0


module texture_cache$banks$3$tags$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [18:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [18:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[18:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$3$tags$1


module texture_cache$banks$3$victim(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [5:0] read_address;
    input wire  read_clock;
    output reg  [1:0] read_data;
    input wire  [5:0] write_address;
    input wire  write_clock;
    input wire  [1:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[1:0] mem[63:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$3$victim


module texture_cache$banks$3$words$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$3$words$0


module texture_cache$banks$3$words$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [7:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [7:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[255:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // texture_cache$banks$3$words$1


module texture_cache$clr(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$clr


module texture_cache$fills_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$fills_r


module texture_cache$flush_pend(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$flush_pend


module texture_cache$hits_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$hits_r


module texture_cache$iss_mask(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$iss_mask


module texture_cache$iss_word(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$iss_word


module texture_cache$misses_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$misses_r


module texture_cache$o_data$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$o_data$0


module texture_cache$o_data$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$o_data$1


module texture_cache$o_data$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$o_data$2


module texture_cache$o_data$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$o_data$3


module texture_cache$o_side(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$o_side


module texture_cache$o_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$o_valid


module texture_cache$rcv_mask(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$rcv_mask


module texture_cache$rcv_word(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$rcv_word


module texture_cache$s1_addr$0(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_addr$0


module texture_cache$s1_addr$1(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_addr$1


module texture_cache$s1_addr$2(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_addr$2


module texture_cache$s1_addr$3(d,q,clock);
    
    // Module arguments
    input wire  [25:0] d;
    output reg  [25:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 26'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_addr$3


module texture_cache$s1_en(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_en


module texture_cache$s1_fresh(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_fresh


module texture_cache$s1_side(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_side


module texture_cache$s1_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$s1_valid


module texture_cache$st(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // texture_cache$st
